// Chi-square goodness-of-fit test of a direction sampler against the density it claims, in the
// style of Mitsuba's tester: bins over the sphere in (cos theta, phi), expected counts from
// numerically integrating the pdf, low-count bins pooled, and outright failure when a sample lands
// where the pdf integrates to zero.
#pragma once

#include "core/math.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

namespace pt::test {

// A small reproducible stream of uniform floats in [0, 1) for tests: a 64-bit LCG's high bits.
struct TestStream {
    uint64_t state;
    float next() {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        return float((state >> 40) * 0x1p-24);
    }
};

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

// The unit direction at polar angle theta from +z and azimuth phi.
inline Vec3 fromAngles(double theta, double phi) {
    return Vec3(float(std::sin(theta) * std::cos(phi)), float(std::sin(theta) * std::sin(phi)), float(std::cos(theta)));
}

struct ChiSquareResult {
    bool pass = false;
    double pValue = 0.0;
    std::string report;
};

// The statistic over counts whose last bin is "no sample": bins expected below 5 are pooled so
// that the chi-square approximation holds, and a pool holding far more samples than expected is
// a failure by itself. More than `minDof` degrees of freedom are required (a sampler whose
// every sample is a delta lobe has none). `total` is the integral of the pdf, for the report.
inline ChiSquareResult chiSquareOfCounts(const std::vector<double>& observed, const std::vector<double>& expected,
                                         double total, int samples, double pAlpha, int minDof = -1) {
    ChiSquareResult result;
    std::ostringstream report;
    double chi2 = 0.0, pooledObs = 0.0, pooledExp = 0.0;
    int dof = -1;
    for (size_t i = 0; i < expected.size(); ++i) {
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
    result.pass = result.pValue > pAlpha && dof > minDof;
    report << "chi2 = " << chi2 << ", dof = " << dof << ", p = " << result.pValue << ", integral of pdf = " << total
           << ", no-sample fraction observed " << observed.back() / samples;
    result.report = report.str();
    return result;
}

// `sample(u, dir)` draws one direction from two uniform numbers; it returns false when it
// produces nothing that the pdf describes (a delta lobe, an absorbed sample). `pdf(dir)` is the
// claimed solid-angle density; its integral may be below 1, the rest counts as "no sample".
inline ChiSquareResult chiSquareDirections(const std::function<bool(Vec2, Vec3&)>& sample,
                                           const std::function<double(const Vec3&)>& pdf, int samples = 200000,
                                           double alpha = 1e-4, int thetaBins = 10, int phiBins = 20,
                                           uint64_t seed = 1) {
    const int bins = thetaBins * phiBins;
    std::vector<double> observed(bins + 1, 0.0), expected(bins + 1, 0.0);
    TestStream stream{seed * 0x9E3779B97F4A7C15ULL + 1};
    auto next = [&] { return stream.next(); };
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
    // Expected counts: midpoint rule on a fine grid inside each bin (dw = dz dphi); a bin whose
    // density varies by more than 2x over its grid is summed again 8 times finer, and one over
    // which it varies by more than 100x (a sun's edge: the midpoints misjudge its area by
    // 3e-4 of the whole at 96 per side, 114 samples of 400000) 4 times finer again.
    auto integrateBin = [&](int ti, int pi, int sub, bool& uneven) {
        double z0 = -1.0 + 2.0 * ti / thetaBins, dz = 2.0 / thetaBins / sub;
        double p0 = 2 * M_PI * pi / phiBins, dp = 2 * M_PI / phiBins / sub;
        double integral = 0.0, lo = 1e300, hi = 0.0;
        for (int a = 0; a < sub; ++a)
            for (int b = 0; b < sub; ++b) {
                double z = z0 + (a + 0.5) * dz, phi = p0 + (b + 0.5) * dp;
                double r = std::sqrt(std::max(0.0, 1.0 - z * z));
                double p = pdf(Vec3(float(r * std::cos(phi)), float(r * std::sin(phi)), float(z)));
                lo = std::min(lo, p);
                hi = std::max(hi, p);
                integral += p * dz * dp;
            }
        uneven = hi > (sub < 96 ? 2.0 : 100.0) * lo;
        return integral;
    };
    double total = 0.0;
    for (int ti = 0; ti < thetaBins; ++ti)
        for (int pi = 0; pi < phiBins; ++pi) {
            bool uneven = false;
            double integral = integrateBin(ti, pi, 12, uneven);
            if (uneven) integral = integrateBin(ti, pi, 96, uneven);
            if (uneven) integral = integrateBin(ti, pi, 384, uneven);
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
    return chiSquareOfCounts(observed, expected, total, samples, alpha);
}

// Chi-square test of a sampler of microfacet lobes in the space of their half vectors m (unit,
// m.z > 0), which maps one to one onto the scattered directions of each side (reflection,
// transmission). Bins are uniform in phi and in a = atan(tan(theta_m) / alpha) / (pi / 2), the
// polar angle once the lobe is stretched to alpha = 1, so narrow lobes spread over many bins and
// the density in a stays smooth up to the horizon. `sample(u1, u2, side, m)` draws one sample,
// returning false when it yields none (absorbed, lost); `pdfM(side, m)` is the claimed density of
// m on that side, whose integral over all sides may be below 1 (the rest is "no sample").
inline ChiSquareResult chiSquareHalfVectors(const std::function<bool(float, Vec2, int&, Vec3&)>& sample,
                                            const std::function<double(int, const Vec3&)>& pdfM, float alpha,
                                            int sides = 1, int samples = 400000, double pAlpha = 1e-4,
                                            uint64_t seed = 99) {
    const int na = 24, nphi = 24, perSide = na * nphi, bins = sides * perSide;
    std::vector<double> expected(bins + 1, 0.0), observed(bins + 1, 0.0);
    // Midpoint sums of pdf(theta(a)) sin(theta) dtheta/da over sub-cells; a bin that a cut-off of
    // the density crosses (some midpoints zero, some not) is summed again 16 times finer, one over
    // which it varies by more than 3x 8 times finer.
    auto integrateBin = [&](int side, int i, int j, int sub, bool& straddles, bool& uneven) {
        double sum = 0.0, lo = 1e300, hi = 0.0;
        bool anyZero = false, anyPositive = false;
        for (int si = 0; si < sub; ++si)
            for (int sj = 0; sj < sub; ++sj) {
                double a = (i + (si + 0.5) / sub) / na, da = 1.0 / (na * sub);
                double c = std::cos(0.5 * M_PI * a), sn = std::sin(0.5 * M_PI * a);
                double theta = std::atan2(alpha * sn, c);
                double dThetaDa = 0.5 * M_PI * alpha / (c * c + alpha * alpha * sn * sn);
                double phi = (j + (sj + 0.5) / sub) * 2.0 * M_PI / nphi, dphi = 2.0 * M_PI / (nphi * sub);
                double p = pdfM(side, fromAngles(theta, phi));
                (p > 0.0 ? anyPositive : anyZero) = true;
                double q = p * std::sin(theta) * dThetaDa;
                lo = std::min(lo, q);
                hi = std::max(hi, q);
                sum += q * da * dphi;
            }
        // A cut-off that only grazes the bin misses every midpoint; its edges still show it.
        if (sub < 64)
            for (int e = 0; e <= 64 && !(anyZero && anyPositive); ++e)
                for (int edge = 0; edge < 4; ++edge) {
                    double t = e / 64.0;
                    double a = (i + (edge == 0 ? 0.0 : edge == 1 ? 1.0 : t)) / na;
                    double ph = (j + (edge == 2 ? 0.0 : edge == 3 ? 1.0 : t)) * 2.0 * M_PI / nphi;
                    a = std::clamp(a, 1e-9, 1.0 - 1e-9);
                    double theta = std::atan2(alpha * std::sin(0.5 * M_PI * a), std::cos(0.5 * M_PI * a));
                    (pdfM(side, fromAngles(theta, ph)) > 0.0 ? anyPositive : anyZero) = true;
                }
        straddles = anyZero && anyPositive;
        uneven = hi > 3.0 * lo;
        return sum;
    };
    TestStream stream{seed * 0x9E3779B97F4A7C15ULL + 1};
    auto next = [&] { return stream.next(); };
    for (int k = 0; k < samples; ++k) {
        int side = 0;
        Vec3 m;
        float u1 = next();
        Vec2 u2(next(), next());
        if (!sample(u1, u2, side, m) || !isFinite(m) || side < 0 || side >= sides) {
            observed[bins] += 1;
            continue;
        }
        double a = std::atan2(std::sqrt(double(m.x) * m.x + double(m.y) * m.y), double(alpha) * m.z) / (0.5 * M_PI);
        double phi = std::atan2(double(m.y), double(m.x));
        if (phi < 0) phi += 2 * M_PI;
        int i = std::clamp(int(a * na), 0, na - 1), j = std::min(nphi - 1, int(phi / (2 * M_PI) * nphi));
        observed[side * perSide + i * nphi + j] += 1;
    }
    // Expected counts; a bin that holds samples but whose coarse sum is zero may hold a sliver of
    // support between the sub-cell midpoints, so it too is summed finer.
    double total = 0.0;
    for (int side = 0; side < sides; ++side)
        for (int i = 0; i < na; ++i)
            for (int j = 0; j < nphi; ++j) {
                bool straddles = false, uneven = false;
                double v = integrateBin(side, i, j, 16, straddles, uneven);
                if (straddles || (v == 0.0 && observed[side * perSide + i * nphi + j] > 0))
                    v = integrateBin(side, i, j, 256, straddles, uneven);
                else if (uneven) // steep (grazing views pile visible normals up towards wo)
                    v = integrateBin(side, i, j, 128, straddles, uneven);
                expected[side * perSide + i * nphi + j] = v * samples;
                total += v;
            }
    expected[bins] = std::max(0.0, 1.0 - total) * samples;
    // A few samples may land in a bin whose sub-cells all miss a sliver of support (at the
    // horizon, at a cut-off); more is a sample where the density is zero.
    for (int b = 0; b < bins; ++b)
        if (expected[b] == 0.0 && observed[b] > 3) {
            ChiSquareResult result;
            result.report = "side " + std::to_string(b / perSide) + " bin " + std::to_string(b % perSide) + ": " +
                            std::to_string(observed[b]) + " samples where the pdf is 0";
            return result;
        }
    return chiSquareOfCounts(observed, expected, total, samples, pAlpha, 10);
}

} // namespace pt::test
