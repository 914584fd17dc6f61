// Chi-square goodness-of-fit test of a direction sampler against the density it claims, in the
// style of Mitsuba's tester: bins over the sphere in (cos theta, phi), expected counts from
// numerically integrating the pdf, low-count bins pooled, and outright failure when a sample lands
// where the pdf integrates to zero.
#pragma once

#include "core/math.h"

#include <cmath>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

namespace pt::test {

// P(X > x) for X ~ chi-square with k degrees of freedom (regularized upper gamma Q(k/2, x/2)).
inline double chiSquareSurvival(double x, double k) {
    double a = 0.5 * k, z = 0.5 * x;
    if (z <= 0) return 1.0;
    double lnPrefix = a * std::log(z) - z - std::lgamma(a);
    if (z < a + 1.0) { // series for P, then Q = 1 - P
        double term = 1.0 / a, sum = term;
        for (int n = 1; n < 10000; ++n) {
            term *= z / (a + n);
            sum += term;
            if (term < sum * 1e-15) break;
        }
        return std::max(0.0, 1.0 - std::exp(lnPrefix) * sum);
    }
    // Continued fraction for Q (modified Lentz).
    double b = z + 1.0 - a, c = 1e300, d = 1.0 / b, h = d;
    for (int i = 1; i < 10000; ++i) {
        double an = -i * (i - a);
        b += 2.0;
        d = an * d + b;
        if (std::abs(d) < 1e-300) d = 1e-300;
        c = b + an / c;
        if (std::abs(c) < 1e-300) c = 1e-300;
        d = 1.0 / d;
        double delta = d * c;
        h *= delta;
        if (std::abs(delta - 1.0) < 1e-15) break;
    }
    return std::exp(lnPrefix) * h;
}

struct ChiSquareResult {
    bool pass = false;
    double pValue = 0.0;
    std::string report;
};

// `sample(u, dir)` draws one direction from two uniform numbers; it returns false when it
// produces nothing that the pdf describes (a delta lobe, an absorbed sample). `pdf(dir)` is the
// claimed solid-angle density; its integral may be below 1, the rest counts as "no sample".
inline ChiSquareResult chiSquareDirections(const std::function<bool(Vec2, Vec3&)>& sample,
                                           const std::function<double(const Vec3&)>& pdf, int samples = 200000,
                                           double alpha = 1e-4, int thetaBins = 10, int phiBins = 20,
                                           uint64_t seed = 1) {
    const int bins = thetaBins * phiBins;
    std::vector<double> observed(bins + 1, 0.0), expected(bins + 1, 0.0);
    // Samples: a simple LCG-free stream from std::hash mixing; quality is ample for this.
    uint64_t state = seed * 0x9E3779B97F4A7C15ULL + 1;
    auto next = [&] {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        return float((state >> 40) * 0x1p-24);
    };
    auto binOf = [&](const Vec3& d) {
        double z = std::clamp(double(d.z), -1.0, 1.0);
        double phi = std::atan2(double(d.y), double(d.x));
        if (phi < 0) phi += 2 * M_PI;
        int ti = std::min(thetaBins - 1, int((z + 1.0) * 0.5 * thetaBins));
        int pi = std::min(phiBins - 1, int(phi / (2 * M_PI) * phiBins));
        return ti * phiBins + pi;
    };
    for (int i = 0; i < samples; ++i) {
        Vec3 d;
        Vec2 u(next(), next());
        if (sample(u, d) && isFinite(d)) observed[binOf(d)] += 1;
        else observed[bins] += 1;
    }
    // Expected counts: midpoint rule on a fine grid inside each bin (dw = dz dphi).
    const int sub = 12;
    double total = 0.0;
    for (int ti = 0; ti < thetaBins; ++ti)
        for (int pi = 0; pi < phiBins; ++pi) {
            double z0 = -1.0 + 2.0 * ti / thetaBins, dz = 2.0 / thetaBins / sub;
            double p0 = 2 * M_PI * pi / phiBins, dp = 2 * M_PI / phiBins / sub;
            double integral = 0.0;
            for (int a = 0; a < sub; ++a)
                for (int b = 0; b < sub; ++b) {
                    double z = z0 + (a + 0.5) * dz, phi = p0 + (b + 0.5) * dp;
                    double r = std::sqrt(std::max(0.0, 1.0 - z * z));
                    integral += pdf(Vec3(float(r * std::cos(phi)), float(r * std::sin(phi)), float(z))) * dz * dp;
                }
            expected[ti * phiBins + pi] = integral * samples;
            total += integral;
        }
    expected[bins] = std::max(0.0, 1.0 - total) * samples;

    ChiSquareResult result;
    std::ostringstream report;
    // A sample where the pdf is zero is a failure no statistic can excuse.
    for (int i = 0; i < bins; ++i)
        if (expected[i] == 0.0 && observed[i] > 0) {
            report << "bin " << i << ": " << observed[i] << " samples where the pdf integrates to 0";
            result.report = report.str();
            return result;
        }
    // Pool bins with small expectations so the chi-square approximation holds.
    double chi2 = 0.0, pooledObs = 0.0, pooledExp = 0.0;
    int dof = -1;
    for (int i = 0; i <= bins; ++i) {
        if (expected[i] < 5.0) {
            pooledObs += observed[i];
            pooledExp += expected[i];
            continue;
        }
        chi2 += (observed[i] - expected[i]) * (observed[i] - expected[i]) / expected[i];
        ++dof;
    }
    if (pooledExp >= 5.0) {
        chi2 += (pooledObs - pooledExp) * (pooledObs - pooledExp) / pooledExp;
        ++dof;
    } else if (pooledObs > 5.0 * std::max(1.0, pooledExp) + 10.0) {
        report << "pooled low-density bins hold " << pooledObs << " samples, expected " << pooledExp;
        result.report = report.str();
        return result;
    }
    result.pValue = dof > 0 ? chiSquareSurvival(chi2, dof) : 1.0;
    result.pass = result.pValue > alpha;
    report << "chi2 = " << chi2 << ", dof = " << dof << ", p = " << result.pValue << ", integral of pdf = " << total
           << ", no-sample fraction observed " << observed[bins] / samples;
    result.report = report.str();
    return result;
}

} // namespace pt::test
