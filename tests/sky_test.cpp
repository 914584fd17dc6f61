// The Preetham sky and sun: the model against the paper's formulas and independently computed
// values, the sky's stability over the whole sphere, the sun's radiance against its spectrum, the
// baked map against the model, and renders whose result is known or must agree between strategies.
#include "light/light_set.h"
#include "environment/sky_environment.h"
#include "environment/sunlight.h"
#include "sampling/rng.h"
#include "sampling/warp.h"
#include "tests/test_scenes.h"

#include <gtest/gtest.h>

#include <cmath>

namespace pt::test {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

// The paper's zenith formulas (Appendix A.2), evaluated independently in Python with numpy from
// the published coefficients: Y_z in kcd/m^2, x_z, y_z.
TEST(PreethamSky, ZenithValuesMatchThePaper) {
    struct Row {
        double t, thetaDegrees, Y, x, y;
    } rows[] = {
        {2, 0, 15.500672, 0.266740, 0.277200},  {2, 30, 5.886743, 0.251421, 0.255924},
        {2, 60, 3.487327, 0.238013, 0.241988},  {2, 85, 2.221547, 0.269004, 0.285803},
        {3, 0, 29.477313, 0.270680, 0.282360},  {3, 45, 7.320358, 0.245678, 0.251476},
        {3, 75, 3.372057, 0.256006, 0.268658},  {5, 30, 18.484167, 0.259287, 0.269823},
        {5, 85, 2.415901, 0.280624, 0.301319},  {10, 0, 76.355595, 0.298260, 0.318480},
        {10, 60, 14.360297, 0.292367, 0.314814}, {10, 85, 2.503446, 0.310683, 0.337436},
    };
    for (const Row& r : rows) {
        double theta = r.thetaDegrees * kDeg;
        EXPECT_NEAR(zenithLuminance(r.t, theta), r.Y, 1e-5 * r.Y) << "T " << r.t << ", theta " << r.thetaDegrees;
        EXPECT_NEAR(zenithChromaticityX(r.t, theta), r.x, 2e-6) << "T " << r.t << ", theta " << r.thetaDegrees;
        EXPECT_NEAR(zenithChromaticityY(r.t, theta), r.y, 2e-6) << "T " << r.t << ", theta " << r.thetaDegrees;
    }
}

SkyParameters skyAt(double elevationDegrees, double azimuthDegrees, float turbidity) {
    SkyParameters p;
    p.sunDirection = sunDirectionFromAngles(elevationDegrees, azimuthDegrees);
    p.turbidity = turbidity;
    return p;
}

// Direction at zenith angle theta and angle gamma from a sun in the x-y plane (azimuth 90).
Vec3 viewAt(double thetaS, double theta, double gamma) {
    // Sun s = (sin ts, cos ts, 0); d = (sin t cos p, cos t, sin t sin p) with cos(gamma) = s.d.
    double cosPhi = std::sin(theta) > 0 ? (std::cos(gamma) - std::cos(theta) * std::cos(thetaS)) /
                                              (std::sin(theta) * std::sin(thetaS))
                                        : 1.0;
    double phi = std::acos(std::clamp(cosPhi, -1.0, 1.0));
    return Vec3(float(std::sin(theta) * std::cos(phi)), float(std::cos(theta)), float(std::sin(theta) * std::sin(phi)));
}

// The whole distribution at T = 3, sun 45 degrees high, against the same independent evaluation:
// Perez's function normalised at the zenith, in Y, x and y.
TEST(PreethamSky, DistributionMatchesThePaper) {
    PreethamSky sky(skyAt(45.0, 90.0, 3.0f));
    struct Point {
        double theta, gamma, Y, x, y;
    } points[] = {
        {0, 45, 7.320358, 0.245678, 0.251476},
        {45, 0, 28.654828, 0.284253, 0.296955},
        {60, 90, 6.154202, 0.244889, 0.258762},
        {85, 120, 7.801709, 0.298871, 0.310519},
    };
    for (const Point& p : points) {
        Vec3 v = sky.xyY(p.theta * kDeg, p.gamma * kDeg);
        EXPECT_NEAR(v.z, p.Y, 2e-5 * p.Y) << "theta " << p.theta << ", gamma " << p.gamma;
        EXPECT_NEAR(v.x, p.x, 2e-6) << "theta " << p.theta << ", gamma " << p.gamma;
        EXPECT_NEAR(v.y, p.y, 2e-6) << "theta " << p.theta << ", gamma " << p.gamma;
    }
    // The radiance in a direction is that xyY in Rec.709, times 0.06 per kcd/m^2: converted back to
    // XYZ (the exact sRGB matrix), it gives the model's luminance and chromaticity.
    for (const Point& p : points) {
        Spectrum c = sky.skyRadiance(viewAt(45.0 * kDeg, p.theta * kDeg, p.gamma * kDeg)) / kSkyRadiancePerKcd;
        double X = 0.4123908 * c.x + 0.3575843 * c.y + 0.1804808 * c.z;
        double Y = 0.2126390 * c.x + 0.7151687 * c.y + 0.0721923 * c.z;
        double Z = 0.0193308 * c.x + 0.1191948 * c.y + 0.9505322 * c.z;
        EXPECT_NEAR(Y, p.Y, 1e-3 * p.Y) << "theta " << p.theta << ", gamma " << p.gamma;
        EXPECT_NEAR(X / (X + Y + Z), p.x, 2e-4) << "theta " << p.theta << ", gamma " << p.gamma;
        EXPECT_NEAR(Y / (X + Y + Z), p.y, 2e-4) << "theta " << p.theta << ", gamma " << p.gamma;
    }
}

bool finiteNonNegative(const Spectrum& c) { return isFinite(c) && c.x >= 0.0f && c.y >= 0.0f && c.z >= 0.0f; }

// Where models fail: every turbidity allowed, the sun at the zenith, on and below the horizon;
// directions on the horizon, at the nadir and straight at the sun.
TEST(PreethamSky, NoNanOrNegativeRadianceAnywhere) {
    for (float t : {kMinTurbidity, 2.0f, 3.0f, 6.0f, kMaxTurbidity})
        for (double elevation : {90.0, 89.99, 45.0, 5.0, 0.01, 0.0, -0.1, -30.0, -90.0}) {
            SkyParameters p = skyAt(elevation, 30.0, t);
            PreethamSky sky(p);
            std::string where = "T " + std::to_string(t) + ", elevation " + std::to_string(elevation);
            ASSERT_TRUE(finiteNonNegative(sky.sunRadiance())) << where;
            ASSERT_TRUE(finiteNonNegative(sky.groundIrradiance())) << where;
            EXPECT_GT(luminance(sky.groundIrradiance()), 0.0f) << where;
            std::vector<Vec3> dirs = {p.sunDirection, Vec3(0, 1, 0), Vec3(0, -1, 0), Vec3(1, 0, 0), Vec3(0, 0, -1)};
            for (int i = 0; i <= 180; ++i)
                for (int j = 0; j < 72; ++j) {
                    double theta = i * kDeg, phi = j * 5.0 * kDeg;
                    dirs.push_back(Vec3(float(std::sin(theta) * std::cos(phi)), float(std::cos(theta)),
                                        float(std::sin(theta) * std::sin(phi))));
                }
            for (const Vec3& d : dirs) {
                Spectrum c = sky.radiance(d);
                ASSERT_TRUE(finiteNonNegative(c)) << where << ", direction " << d.x << " " << d.y << " " << d.z;
            }
            EXPECT_GT(luminance(sky.skyRadiance(Vec3(0, 1, 0))), 0.0f) << where;
        }
}

// Below the horizon the sky is that of a sun on it, and the disk is hidden: a documented choice.
TEST(PreethamSky, SunBelowTheHorizonIsHidden) {
    PreethamSky below(skyAt(-5.0, 30.0, 3.0f)), onHorizon(skyAt(0.0, 30.0, 3.0f));
    EXPECT_TRUE(isBlack(below.sunRadiance()));
    EXPECT_FALSE(isBlack(onHorizon.sunRadiance())); // the upper half of its disk still shows
    EXPECT_NEAR(below.modelSunZenith(), 0.5 * 3.14159265358979, 1e-9);
    // The sky of a sun 5, 30, 60 or 90 degrees below is exactly that of the sun on the horizon at
    // the same azimuth, gamma included (it once kept gamma to the sun below the horizon, so the sky
    // at -30 and -60 differed though the README and the warning said otherwise).
    for (double elevation : {-5.0, -30.0, -60.0, -89.0}) {
        PreethamSky deep(skyAt(elevation, 30.0, 3.0f));
        for (Vec3 d : {Vec3(0.3f, 0.5f, -0.2f), Vec3(-0.8f, 0.1f, 0.4f), Vec3(0.0f, 1.0f, 0.0f), Vec3(0.5f, 0.01f, -0.87f)}) {
            d = glm::normalize(d);
            Spectrum a = deep.skyRadiance(d), b = onHorizon.skyRadiance(d);
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], b[c], 1e-5f * b[c]) << elevation << " degrees, channel " << c;
        }
        EXPECT_NEAR(luminance(deep.groundIrradiance()), luminance(below.groundIrradiance()), 1e-5f * luminance(below.groundIrradiance()));
    }
    Environment env = skyEnvironment(skyAt(-5.0, 30.0, 3.0f));
    EXPECT_FALSE(env.sun);
    ASSERT_TRUE(env.preetham);
}

// The sun's spectral radiance through the atmosphere, against an independent evaluation of the
// same formulas (Python, 5 nm steps): optical mass, transmittances, luminance and chromaticity.
TEST(Sunlight, MatchesTheSpectralReference) {
    EXPECT_NEAR(relativeOpticalMass(0.0), 0.999494, 1e-6);
    EXPECT_NEAR(relativeOpticalMass(45 * kDeg), 1.411923, 1e-6);
    EXPECT_NEAR(relativeOpticalMass(80 * kDeg), 5.580339, 1e-6);
    struct Tau {
        double t, theta, nm, expected;
    } taus[] = {
        {2, 0, 550, 0.904762 * 0.904220 * 0.970703},
        {2, 0, 720, 0.967198 * 0.931517 * 0.995114 * 0.914359},
        {2, 0, 760, 0.973605 * 0.936013 * 0.997554 * 0.740836 * 0.999995},
        {5, 60, 400, 0.481106 * 0.298093 * 0.998954},
        {5, 60, 700, 0.928118 * 0.557252 * 0.984086 * 0.986013},
    };
    for (const Tau& c : taus)
        EXPECT_NEAR(atmosphereTransmittance(c.t, c.theta * kDeg, c.nm), c.expected, 3e-6)
            << "T " << c.t << ", theta " << c.theta << ", " << c.nm << " nm";
    struct Sun {
        double t, theta, luminance, x, y;
    } suns[] = {
        {2, 0, 1.4966e9, 0.3304, 0.3404},
        {3, 45, 1.1846e9, 0.3409, 0.3501},
        {5, 60, 6.6238e8, 0.3651, 0.3692},
        {2, 80, 5.3022e8, 0.3906, 0.3908},
    };
    for (const Sun& s : suns) {
        SunlightXyz v = sunRadianceXyz(s.t, s.theta * kDeg);
        double sum = v.X + v.Y + v.Z;
        EXPECT_NEAR(v.Y, s.luminance, 1e-4 * s.luminance) << "T " << s.t << ", theta " << s.theta;
        EXPECT_NEAR(v.X / sum, s.x, 1e-4) << "T " << s.t << ", theta " << s.theta;
        EXPECT_NEAR(v.Y / sum, s.y, 1e-4) << "T " << s.t << ", theta " << s.theta;
    }
}

// Physical sanity of the units: outside the atmosphere the sun's disk gives the solar
// illuminance constant (about 128 to 134 klx, less the little light outside 380 to 750 nm), and a
// clear high sun about 100 klx at the ground.
TEST(Sunlight, IlluminanceIsTheSunsOnEarth) {
    double solidAngle = 2.0 * 3.14159265358979 * (1.0 - std::cos(kSunAngularRadius));
    double outside = extraterrestrialSunRadianceXyz().Y * solidAngle;
    EXPECT_GT(outside, 120e3);
    EXPECT_LT(outside, 134e3);
    double ground = sunRadianceXyz(2.0, 0.0).Y * solidAngle;
    EXPECT_GT(ground, 90e3);
    EXPECT_LT(ground, 110e3);
}

// The sun's disk, as the light set samples it, integrates to the model's irradiance: an NEE
// estimate of the irradiance on a surface facing the sun, in lux, equals the sun's luminance
// times its solid angle. Also for a surface tilted by 60 degrees (cosine law) and for one facing
// away (nothing).
TEST(SunDisk, IntegratesToTheModelsIrradiance) {
    SkyParameters p = skyAt(50.0, 200.0, 2.5f);
    Scene scene = emptyScene(lookAt({0, 0, 4}, {0, 0, 0}, 40));
    scene.environment = skyEnvironment(p);
    ASSERT_TRUE(scene.environment.sun);
    LightSet lights(scene);
    uint32_t e = lights.sunEmitter();
    ASSERT_NE(e, ~0u);
    double theta = 40.0 * kDeg;
    SunlightXyz model = sunRadianceXyz(2.5, theta);
    PreethamSky sky(p);
    double expectedLux = model.Y * sky.sunSolidAngle();
    Frame sunFrame(p.sunDirection);
    for (double tilt : {0.0, 60.0, 180.0}) {
        Vec3 n = sunFrame.toWorld(Vec3(float(std::sin(tilt * kDeg)), 0.0f, float(std::cos(tilt * kDeg))));
        Pcg32 rng(7, 1);
        double sum = 0.0;
        const int N = 200000;
        for (int i = 0; i < N; ++i) {
            LightSample s = lights.sample(e, Vec3(0), Vec2(rng.nextFloat(), rng.nextFloat()));
            ASSERT_GT(s.pdf, 0.0f);
            EXPECT_FLOAT_EQ(s.pdf, lights.pdf(e, Vec3(0), s.wi, kInf));
            sum += double(luminance(s.radiance)) * std::max(0.0f, glm::dot(n, s.wi)) / s.pdf;
        }
        double lux = sum / N / (kSkyRadiancePerKcd * 1e-3);
        double expected = expectedLux * std::max(0.0, std::cos(tilt * kDeg));
        EXPECT_NEAR(lux, expected, 2e-3 * expectedLux) << "tilt " << tilt;
    }
}

// The map baked at 512 x 256 against the model it was baked from, away from the horizon's
// two-texel band where sky and ground are blended, and from the cusp of Perez's circumsolar term
// at the sun (within 2 degrees of it; the sun's disk, 1e5 times brighter, is where the error peaks).
TEST(SkyEnvironment, BakedMapMatchesTheModel) {
    for (double elevation : {60.0, 20.0, 3.0}) {
        SkyParameters p = skyAt(elevation, 75.0, 3.0f);
        PreethamSky sky(p);
        EnvironmentMap map = bakeSky(sky);
        ASSERT_EQ(map.width, 512);
        ASSERT_EQ(map.height, 256);
        Pcg32 rng(3, 1);
        float worst = 0.0f;
        double sum = 0.0;
        int n = 0;
        for (int i = 0; i < 50000; ++i) {
            Vec3 d = squareToUniformSphere(Vec2(rng.nextFloat(), rng.nextFloat()));
            if (std::abs(d.y) < std::sin(1.0f * float(kDeg))) continue;
            Spectrum a = sky.radiance(d), b = map.radiance(d);
            float error = std::abs(luminance(a) - luminance(b)) / luminance(a);
            sum += error, ++n;
            if (glm::dot(d, p.sunDirection) < std::cos(2.0f * float(kDeg))) worst = std::max(worst, error);
        }
        EXPECT_LT(worst, 1e-3f) << "elevation " << elevation;
        EXPECT_LT(sum / n, 3e-5) << "elevation " << elevation; // the mean, cusp included
    }
}

// The ground below the horizon reflects albedo 0.2 of the light on a horizontal plane: the sky's,
// integrated here by Monte Carlo independently of the model's quadrature, and the sun's.
TEST(SkyEnvironment, GroundIsAlbedoTimesTheIrradiance) {
    SkyParameters p = skyAt(35.0, 10.0, 4.0f);
    PreethamSky sky(p);
    Pcg32 rng(11, 1);
    Spectrum skySum(0.0f);
    const int N = 400000;
    for (int i = 0; i < N; ++i) {
        Vec3 d = squareToCosineHemisphere(Vec2(rng.nextFloat(), rng.nextFloat()));
        skySum += sky.skyRadiance(Vec3(d.x, d.z, d.y)); // hemisphere about +y
    }
    Spectrum skyIrradiance = skySum * (kPi / N);
    Spectrum expected = skyIrradiance + sky.sunNormalIrradiance() * float(std::sin(35.0 * kDeg));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(sky.groundIrradiance()[c], expected[c], 3e-3f * expected[c]);
    Spectrum ground = sky.radiance(Vec3(0, -1, 0));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(ground[c], kGroundAlbedo / kPi * expected[c], 3e-3f * ground[c]);
}

TEST(SkyEnvironment, SunAnglesFollowTheCompass) {
    auto expectDir = [](Vec3 got, Vec3 want) {
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], 1e-6f) << c;
    };
    expectDir(sunDirectionFromAngles(0, 0), Vec3(0, 0, -1));
    expectDir(sunDirectionFromAngles(0, 90), Vec3(1, 0, 0));
    expectDir(sunDirectionFromAngles(0, 180), Vec3(0, 0, 1));
    expectDir(sunDirectionFromAngles(0, 270), Vec3(-1, 0, 0));
    expectDir(sunDirectionFromAngles(90, 123), Vec3(0, 1, 0));
    Vec3 d = sunDirectionFromAngles(25, 300);
    EXPECT_NEAR(sunElevationDegrees(d), 25.0, 1e-4);
    EXPECT_NEAR(sunAzimuthDegrees(d), 300.0, 1e-4);
}

// A white Lambert plane seeing the whole sky, direct light only: its radiance is 1/pi of the
// horizontal irradiance of sky and sun, whichever strategy finds the light.
TEST(SkyRender, PlaneReflectsTheHorizontalIrradiance) {
    Scene scene = emptyScene(lookAt({0, 3, 0.01f}, {0, 0, 0}, 20));
    Material white;
    white.kd = Spectrum(1.0f);
    addQuad(scene, Vec3(-50, 0, 50), Vec3(50, 0, 50), Vec3(50, 0, -50), Vec3(-50, 0, -50), addMaterial(scene, white));
    SkyParameters p = skyAt(40.0, 60.0, 3.0f);
    p.sunAngularRadius = 2.0 * kDeg; // wide enough for BSDF sampling to find it at test sample counts
    scene.environment = skyEnvironment(p);
    PreethamSky sky(p);
    Spectrum expected = sky.groundIrradiance() * kInvPi;
    for (LightSampling mode : {LightSampling::Mis, LightSampling::Nee, LightSampling::Bsdf}) {
        RenderSettings s;
        s.lightSampling = mode;
        s.maxDepth = 1;
        Rendered r = render(scene, 16, 16, mode == LightSampling::Bsdf ? 4096 : 256, s);
        // The horizontal irradiance is a midpoint-rule quadrature, good to about 1e-4.
        expectNear(regionStats(r, 0, 0, 16, 16), expected, 5.0f, 3e-4f, modeName(mode).c_str());
    }
}

// Light sampling, BSDF sampling and MIS converge to the same image under the sky, with a sun
// widened to 3 degrees so that BSDF sampling alone finds it.
TEST(SkyRender, StrategiesAgree) {
    Scene scene = groundScene();
    SkyParameters p = skyAt(30.0, 230.0, 3.0f);
    p.sunAngularRadius = 3.0 * kDeg;
    scene.environment = skyEnvironment(p);
    expectStrategiesAgree(scene);
}

} // namespace
} // namespace pt::test
