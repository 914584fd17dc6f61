#include "image/flip.h"

#include <glm/glm.hpp>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace pt {
namespace {

using Color = glm::vec3;
constexpr float kPi = 3.14159265358979f;

// The paper's constants: colour error exponent qc, the knee pc and its value pt, the feature
// detector's width w (degrees) and feature exponent qf.
constexpr float kQc = 0.7f, kPc = 0.4f, kPt = 0.95f, kW = 0.082f, kQf = 0.5f;

// Linear sRGB to CIE XYZ for the D65 white, and back; the white is the matrix's row sums.
const glm::mat3 kRgbToXyz = glm::transpose(glm::mat3(0.4123865633f, 0.3575914909f, 0.1804504912f,  //
                                                     0.2126368217f, 0.7151829818f, 0.0721801965f,  //
                                                     0.0193306202f, 0.1191971636f, 0.9503725870f));
const glm::mat3 kXyzToRgb = glm::inverse(kRgbToXyz);
const Color kWhite = kRgbToXyz * Color(1.0f);

// YCxCz: CIELAB without its cube root, a linear opponent space in which to filter.
Color xyzToYcxcz(Color xyz) {
    Color n = xyz / kWhite;
    return {116.0f * n.y - 16.0f, 500.0f * (n.x - n.y), 200.0f * (n.y - n.z)};
}

Color ycxczToXyz(Color c) {
    float y = (c.x + 16.0f) / 116.0f;
    return Color(y + c.y / 500.0f, y, y - c.z / 200.0f) * kWhite;
}

Color xyzToLab(Color xyz) {
    constexpr float d = 6.0f / 29.0f;
    auto f = [&](float t) { return t > d * d * d ? std::cbrt(t) : t / (3.0f * d * d) + 4.0f / 29.0f; };
    Color n = xyz / kWhite;
    float fx = f(n.x), fy = f(n.y), fz = f(n.z);
    return {116.0f * fy - 16.0f, 500.0f * (fx - fy), 200.0f * (fy - fz)};
}

// Lab with the Hunt effect: chroma is less visible at low lightness.
Color huntLab(Color linearRgb) {
    Color lab = xyzToLab(kRgbToXyz * linearRgb);
    return {lab.x, 0.01f * lab.x * lab.y, 0.01f * lab.x * lab.z};
}

// HyAB: city-block distance in lightness, Euclidean in the chromatic plane.
float hyab(Color a, Color b) {
    return std::abs(a.x - b.x) + std::hypot(a.y - b.y, a.z - b.z);
}

// The contrast sensitivity functions as spatial filters: for each opponent channel a sum of
// Gaussians a * sqrt(pi / b) * exp(-pi^2 r^2 / b), r in degrees. Achromatic and red-green have
// one term, blue-yellow two; each 2D kernel sums to 1.
struct CsfTerm {
    float a, b;
};
constexpr CsfTerm kAchromatic{1.0f, 0.0047f}, kRedGreen{1.0f, 0.0053f};
constexpr CsfTerm kBlueYellow1{34.1f, 0.04f}, kBlueYellow2{13.5f, 0.025f};

// 1D factors of the CSF kernels: a 2D Gaussian term is the product of two 1D ones, so the
// blue-yellow kernel is the sum of two separable filters.
struct CsfFilters {
    int radius = 0;
    std::vector<float> y, cx, cz1, cz2;
};

CsfFilters makeCsfFilters(float ppd) {
    CsfFilters f;
    float widest = std::max({kAchromatic.b, kRedGreen.b, kBlueYellow1.b, kBlueYellow2.b});
    f.radius = int(std::ceil(3.0f * std::sqrt(widest / (2.0f * kPi * kPi)) * ppd));
    int n = 2 * f.radius + 1;
    auto factor = [](CsfTerm t, float d2) { return std::sqrt(t.a * std::sqrt(kPi / t.b)) * std::exp(-kPi * kPi * d2 / t.b); };
    double sy = 0, scx = 0, s1 = 0, s2 = 0;
    for (int i = 0; i < n; ++i) {
        float d = float(i - f.radius) / ppd;
        f.y.push_back(factor(kAchromatic, d * d));
        f.cx.push_back(factor(kRedGreen, d * d));
        f.cz1.push_back(factor(kBlueYellow1, d * d));
        f.cz2.push_back(factor(kBlueYellow2, d * d));
        sy += f.y.back(), scx += f.cx.back(), s1 += f.cz1.back(), s2 += f.cz2.back();
    }
    float nz = float(1.0 / std::sqrt(s1 * s1 + s2 * s2)); // 2D sum of both terms is s1^2 + s2^2
    for (int i = 0; i < n; ++i) {
        f.y[i] /= float(sy), f.cx[i] /= float(scx), f.cz1[i] *= nz, f.cz2[i] *= nz;
    }
    return f;
}

// Edge and point detectors: a Gaussian of standard deviation w/2 degrees and its first and
// second derivatives, their positive and negative weights each normalised to +-1.
struct FeatureFilters {
    int radius = 0;
    std::vector<float> g, dg, ddg;
};

FeatureFilters makeFeatureFilters(float ppd) {
    FeatureFilters f;
    float sigma = 0.5f * kW * ppd;
    f.radius = int(std::ceil(3.0f * sigma));
    double sg = 0, dPos = 0, dNeg = 0, ddPos = 0, ddNeg = 0;
    for (int i = -f.radius; i <= f.radius; ++i) {
        float x = float(i);
        float g = std::exp(-x * x / (2.0f * sigma * sigma));
        float dg = -x * g, ddg = (x * x / (sigma * sigma) - 1.0f) * g;
        f.g.push_back(g), f.dg.push_back(dg), f.ddg.push_back(ddg);
        sg += g;
        (dg > 0 ? dPos : dNeg) += std::abs(dg);
        (ddg > 0 ? ddPos : ddNeg) += std::abs(ddg);
    }
    for (size_t i = 0; i < f.g.size(); ++i) {
        f.g[i] /= float(sg);
        f.dg[i] /= float(f.dg[i] > 0 ? dPos : dNeg);
        f.ddg[i] /= float(f.ddg[i] > 0 ? ddPos : ddNeg);
    }
    return f;
}

// One pass of a separable convolution, along rows or along columns, with clamp-to-edge borders.
// `taps(k, in, acc)` adds tap k's weights times the In channels of a pixel into Out accumulators.
template <size_t N>
using Pixels = std::vector<std::array<float, N>>;

template <size_t Out, size_t In, typename Taps>
Pixels<Out> convolve(const Pixels<In>& in, int w, int h, int radius, bool alongColumns, const Taps& taps) {
    Pixels<Out> out(in.size());
    tbb::parallel_for(0, h, [&](int y) {
        for (int x = 0; x < w; ++x) {
            std::array<float, Out> acc{};
            for (int k = -radius; k <= radius; ++k) {
                size_t at = alongColumns ? size_t(std::clamp(y + k, 0, h - 1)) * w + x
                                         : size_t(y) * w + std::clamp(x + k, 0, w - 1);
                taps(k + radius, in[at], acc);
            }
            out[size_t(y) * w + x] = acc;
        }
    });
    return out;
}

// Colour error per pixel in [0, 1] from images in YCxCz.
std::vector<float> colorError(const Pixels<3>& test, const Pixels<3>& ref, int w, int h, float ppd) {
    CsfFilters f = makeCsfFilters(ppd);
    // Four filtered values per pixel: Y, Cx, and Cz through each of its two terms.
    auto horizontal = [&](int i, const std::array<float, 3>& p, std::array<float, 4>& acc) {
        acc[0] += f.y[i] * p[0], acc[1] += f.cx[i] * p[1], acc[2] += f.cz1[i] * p[2], acc[3] += f.cz2[i] * p[2];
    };
    auto vertical = [&](int i, const std::array<float, 4>& p, std::array<float, 4>& acc) {
        acc[0] += f.y[i] * p[0], acc[1] += f.cx[i] * p[1], acc[2] += f.cz1[i] * p[2], acc[3] += f.cz2[i] * p[3];
    };
    auto filtered = [&](const Pixels<3>& img) {
        return convolve<4>(convolve<4>(img, w, h, f.radius, false, horizontal), w, h, f.radius, true, vertical);
    };
    Pixels<4> ft = filtered(test), fr = filtered(ref);

    float cmax = std::pow(hyab(huntLab(Color(0, 1, 0)), huntLab(Color(0, 0, 1))), kQc);
    float knee = kPc * cmax;
    std::vector<float> err(size_t(w) * h);
    for (size_t i = 0; i < err.size(); ++i) {
        auto toLab = [](const std::array<float, 4>& c) {
            Color rgb = glm::clamp(kXyzToRgb * ycxczToXyz(Color(c[0], c[1], c[2] + c[3])), 0.0f, 1.0f);
            return huntLab(rgb);
        };
        float e = std::pow(hyab(toLab(fr[i]), toLab(ft[i])), kQc);
        // Compress large differences: [0, knee) maps to [0, pt), [knee, cmax] to [pt, 1].
        err[i] = e < knee ? e * kPt / knee : kPt + (e - knee) / (cmax - knee) * (1.0f - kPt);
    }
    return err;
}

// Feature error per pixel: the larger difference of edge and point strength of the lightness.
std::vector<float> featureError(const Pixels<3>& test, const Pixels<3>& ref, int w, int h, float ppd) {
    FeatureFilters f = makeFeatureFilters(ppd);
    // Rows: lightness through dg, ddg and g; columns: (dg x g, ddg x g, g x dg, g x ddg).
    auto horizontal = [&](int i, const std::array<float, 1>& p, std::array<float, 3>& acc) {
        acc[0] += f.dg[i] * p[0], acc[1] += f.ddg[i] * p[0], acc[2] += f.g[i] * p[0];
    };
    auto vertical = [&](int i, const std::array<float, 3>& p, std::array<float, 4>& acc) {
        acc[0] += f.g[i] * p[0], acc[1] += f.g[i] * p[1], acc[2] += f.dg[i] * p[2], acc[3] += f.ddg[i] * p[2];
    };
    auto features = [&](const Pixels<3>& img) {
        Pixels<1> lightness(img.size());
        for (size_t i = 0; i < img.size(); ++i) lightness[i][0] = (img[i][0] + 16.0f) / 116.0f; // to [0, 1]
        return convolve<4>(convolve<3>(lightness, w, h, f.radius, false, horizontal), w, h, f.radius, true, vertical);
    };
    Pixels<4> ft = features(test), fr = features(ref);
    std::vector<float> err(size_t(w) * h);
    for (size_t i = 0; i < err.size(); ++i) {
        float edge = std::abs(std::hypot(fr[i][0], fr[i][2]) - std::hypot(ft[i][0], ft[i][2]));
        float point = std::abs(std::hypot(fr[i][1], fr[i][3]) - std::hypot(ft[i][1], ft[i][3]));
        err[i] = std::pow(std::max(edge, point) / std::sqrt(2.0f), kQf);
    }
    return err;
}

Pixels<3> toYcxcz(const std::vector<float>& rgb) {
    Pixels<3> out(rgb.size() / 3);
    for (size_t i = 0; i < out.size(); ++i) {
        Color c = glm::clamp(Color(rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2]), 0.0f, 1.0f);
        Color v = xyzToYcxcz(kRgbToXyz * c);
        out[i] = {v.x, v.y, v.z};
    }
    return out;
}

// The ACES filmic curve as fitted by Narkowicz, after a 0.6 exposure: a ratio of quadratics,
// (k0 x^2 + k1 x) / (k3 x^2 + k4 x + k5).
constexpr float kAces[6] = {0.6f * 0.6f * 2.51f, 0.6f * 0.03f, 0.0f, 0.6f * 0.6f * 2.43f, 0.6f * 0.59f, 0.14f};

float aces(float x) {
    return (x * x * kAces[0] + x * kAces[1] + kAces[2]) / (x * x * kAces[3] + x * kAces[4] + kAces[5]);
}

double meanOf(const std::vector<float>& values) {
    double sum = 0;
    for (float v : values) sum += v;
    return values.empty() ? 0.0 : sum / double(values.size());
}

} // namespace

FlipResult ldrFlip(const std::vector<float>& test, const std::vector<float>& reference, int width, int height, float ppd) {
    Pixels<3> t = toYcxcz(test), r = toYcxcz(reference);
    std::vector<float> color = colorError(t, r, width, height, ppd);
    std::vector<float> feature = featureError(t, r, width, height, ppd);
    FlipResult result;
    result.error.resize(color.size());
    // Features sharpen the colour error: a feature difference of 1 makes any colour error 1.
    for (size_t i = 0; i < color.size(); ++i) result.error[i] = std::pow(color[i], 1.0f - feature[i]);
    result.mean = meanOf(result.error);
    return result;
}

FlipResult hdrFlip(const std::vector<float>& test, const std::vector<float>& reference, int width, int height, float ppd) {
    size_t n = size_t(width) * height;
    // The exposure range: from where the reference's brightest pixel, to where its median pixel,
    // maps to 0.85 through the tone curve (the larger root of aces(x) = 0.85).
    std::vector<float> luminance(n);
    float ymax = 0, ymin = INFINITY;
    for (size_t i = 0; i < n; ++i) {
        luminance[i] = 0.2126f * reference[3 * i] + 0.7152f * reference[3 * i + 1] + 0.0722f * reference[3 * i + 2];
        ymax = std::max(ymax, luminance[i]);
        if (luminance[i] > 0) ymin = std::min(ymin, luminance[i]);
    }
    std::nth_element(luminance.begin(), luminance.begin() + n / 2, luminance.end());
    float ymedian = luminance[n / 2];
    const float t = 0.85f;
    float a = kAces[0] - t * kAces[3], b = kAces[1] - t * kAces[4], c = kAces[2] - t * kAces[5];
    float half = -0.5f * b / a;
    float xmax = half + std::sqrt(half * half - c / a);

    FlipResult result;
    // A black reference, or one mostly black, has no median to expose for: fall back to its
    // darkest lit pixel, or to exposure 0 when nothing is lit.
    if (!(ymedian > 0)) ymedian = std::isfinite(ymin) ? ymin : 1.0f;
    if (!(ymax > 0)) ymax = 1.0f;
    result.startExposure = std::log2(xmax / ymax);
    result.stopExposure = std::log2(xmax / ymedian);
    result.exposures = int(std::max(2.0f, std::ceil(result.stopExposure - result.startExposure)));
    float step = (result.stopExposure - result.startExposure) / float(result.exposures - 1);

    result.error.assign(n, 0.0f);
    std::vector<float> te(3 * n), re(3 * n);
    for (int e = 0; e < result.exposures; ++e) {
        float scale = std::exp2(result.startExposure + float(e) * step);
        for (size_t i = 0; i < 3 * n; ++i) {
            te[i] = aces(std::max(0.0f, test[i]) * scale);
            re[i] = aces(std::max(0.0f, reference[i]) * scale);
        }
        FlipResult ldr = ldrFlip(te, re, width, height, ppd);
        for (size_t i = 0; i < n; ++i) result.error[i] = std::max(result.error[i], ldr.error[i]);
    }
    result.mean = meanOf(result.error);
    return result;
}

} // namespace pt
