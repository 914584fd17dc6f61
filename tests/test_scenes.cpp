#include "tests/test_scenes.h"

#include "accel/accel.h"
#include "image/compare.h"

#include <gtest/gtest.h>

#include <map>

namespace pt::test {

uint32_t addMaterial(Scene& scene, const Material& m) {
    scene.materials.push_back(m);
    return uint32_t(scene.materials.size() - 1);
}

void addTriangle(Scene& scene, Vec3 a, Vec3 b, Vec3 c, uint32_t material) {
    uint32_t base = uint32_t(scene.positions.size());
    scene.positions.insert(scene.positions.end(), {a, b, c});
    scene.triPositions.emplace_back(base, base + 1, base + 2);
    scene.triMaterial.push_back(material);
    if (!scene.triNormals.empty()) scene.triNormals.emplace_back(-1);
    if (!scene.triUvs.empty()) scene.triUvs.emplace_back(-1);
}

void addQuad(Scene& scene, Vec3 a, Vec3 b, Vec3 c, Vec3 d, uint32_t material) {
    addTriangle(scene, a, b, c, material);
    addTriangle(scene, a, c, d, material);
}

void addIcosphere(Scene& scene, Vec3 center, float radius, int subdivisions, uint32_t material, bool inward,
                  bool smooth) {
    const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
    std::vector<Vec3> v = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                           {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    std::vector<glm::uvec3> f = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                                 {11, 10, 2}, {10, 7, 6}, {7, 1, 8},   {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                                 {3, 8, 9},  {4, 9, 5},  {2, 4, 11},  {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    for (Vec3& p : v) p = glm::normalize(p);
    for (int s = 0; s < subdivisions; ++s) {
        std::map<std::pair<uint32_t, uint32_t>, uint32_t> mid;
        auto midpoint = [&](uint32_t a, uint32_t b) {
            auto key = std::minmax(a, b);
            auto it = mid.find(key);
            if (it != mid.end()) return it->second;
            v.push_back(glm::normalize(v[a] + v[b]));
            return mid[key] = uint32_t(v.size() - 1);
        };
        std::vector<glm::uvec3> g;
        for (const glm::uvec3& tri : f) {
            uint32_t ab = midpoint(tri.x, tri.y), bc = midpoint(tri.y, tri.z), ca = midpoint(tri.z, tri.x);
            g.insert(g.end(), {{tri.x, ab, ca}, {tri.y, bc, ab}, {tri.z, ca, bc}, {ab, bc, ca}});
        }
        f = std::move(g);
    }
    uint32_t normalBase = uint32_t(scene.normals.size());
    if (smooth) {
        for (const Vec3& p : v) scene.normals.push_back(inward ? -p : p);
    }
    for (const glm::uvec3& tri : f) {
        Vec3 a = center + radius * v[tri.x], b = center + radius * v[tri.y], c = center + radius * v[tri.z];
        glm::uvec3 corners = inward ? glm::uvec3(tri.x, tri.z, tri.y) : tri;
        if (inward) addTriangle(scene, a, c, b, material);
        else addTriangle(scene, a, b, c, material);
        if (smooth) {
            scene.triNormals.resize(scene.triangleCount(), glm::ivec3(-1)); // the first smooth face
            scene.triNormals.back() = glm::ivec3(glm::uvec3(normalBase) + corners);
        }
    }
}

void addBox(Scene& scene, Vec3 lo, Vec3 hi, uint32_t m) {
    Vec3 p[8];
    for (int i = 0; i < 8; ++i) p[i] = Vec3(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z);
    addQuad(scene, p[0], p[2], p[3], p[1], m); // z = lo, facing -z
    addQuad(scene, p[4], p[5], p[7], p[6], m); // z = hi, facing +z
    addQuad(scene, p[0], p[4], p[6], p[2], m); // x = lo
    addQuad(scene, p[1], p[3], p[7], p[5], m); // x = hi
    addQuad(scene, p[0], p[1], p[5], p[4], m); // y = lo
    addQuad(scene, p[2], p[6], p[7], p[3], m); // y = hi
}

Image toImage(const Rendered& r) {
    Image img;
    img.width = r.width;
    img.height = r.height;
    img.rgb = r.mean;
    img.layers.push_back({"variance", {"R", "G", "B"}, r.variance});
    return img;
}

Camera lookAt(Vec3 from, Vec3 to, Vec3 up, float fov) {
    Camera c;
    c.name = "test";
    c.position = from;
    c.target = to;
    c.up = up;
    c.fovY = fov;
    return c;
}

Camera lookAt(Vec3 from, Vec3 to, float fov) { return lookAt(from, to, Vec3(0, 1, 0), fov); }

std::string modeName(LightSampling m) {
    return m == LightSampling::Mis ? "mis" : m == LightSampling::Nee ? "nee" : "bsdf";
}

Scene emptyScene(const Camera& camera) {
    Scene scene;
    scene.path = "(test)";
    scene.cameras.push_back(camera);
    scene.environment.sky = scene.environment.ground = Spectrum(0.0f);
    return scene;
}

Scene groundScene() {
    Scene scene = emptyScene(lookAt({0, 1.2f, 3.5f}, {0, 0.4f, 0}, 40));
    Material ground, white, gloss;
    ground.kd = Spectrum(0.5f);
    white.kd = Spectrum(0.8f);
    gloss.kd = Spectrum(0.0f);
    gloss.ks = Spectrum(0.95f, 0.75f, 0.45f);
    gloss.metallic = 1.0f;
    gloss.roughness = 0.1f;
    gloss.eta = 1.5f;
    addQuad(scene, Vec3(-4, 0, 4), Vec3(4, 0, 4), Vec3(4, 0, -4), Vec3(-4, 0, -4), addMaterial(scene, ground));
    addIcosphere(scene, Vec3(-0.55f, 0.5f, 0), 0.5f, 3, addMaterial(scene, white), false, true);
    addIcosphere(scene, Vec3(0.55f, 0.5f, 0), 0.5f, 3, addMaterial(scene, gloss), false, true);
    return scene;
}

Rendered render(const Scene& scene, int width, int height, uint32_t spp, const RenderSettings& settings, int threads) {
    Accel accel(scene, threads);
    RenderResult result = renderImage(scene, accel, scene.cameras[0], width, height, spp, threads, settings);
    Rendered r;
    r.width = width;
    r.height = height;
    r.mean = result.film.mean();
    r.variance = result.film.varianceOfMean();
    r.rays = result.rays;
    return r;
}

void expectStrategiesAgree(const Scene& scene) {
    RenderSettings mis;
    mis.seed = 5;
    Rendered reference = render(scene, 32, 24, 1024, mis);
    for (LightSampling mode : {LightSampling::Nee, LightSampling::Bsdf}) {
        RenderSettings s;
        s.lightSampling = mode;
        s.seed = 9;
        expectSameImage(render(scene, 32, 24, mode == LightSampling::Bsdf ? 4096 : 1024, s), reference, modeName(mode));
    }
}

RegionStats regionStats(const Rendered& r, int x0, int y0, int x1, int y1) {
    glm::dvec3 sum(0.0), var(0.0);
    double n = 0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
            size_t i = 3 * (size_t(y) * r.width + x);
            for (int c = 0; c < 3; ++c) {
                sum[c] += r.mean[i + c];
                var[c] += r.variance[i + c];
            }
            n += 1;
        }
    RegionStats s;
    s.mean = Spectrum(sum / n);
    s.stdError = Spectrum(glm::sqrt(var) / n);
    return s;
}

void expectNear(const RegionStats& s, const Spectrum& expected, float sigmas, float relTol, const char* what) {
    for (int c = 0; c < 3; ++c) {
        float tol = sigmas * s.stdError[c] + relTol * std::abs(expected[c]);
        EXPECT_NEAR(s.mean[c], expected[c], tol)
            << what << ", channel " << c << ": standard error " << s.stdError[c];
    }
}

void expectSameImage(const Rendered& test, const Rendered& reference, const std::string& what) {
    CompareOptions options;
    options.blockSize = 8;
    CompareReport report = compareImages(toImage(test), toImage(reference), options);
    EXPECT_TRUE(report.pass) << what << ": " << report.failedTests << " tests differ; worst z " << report.worst[0].z
                             << " at " << report.worst[0].x0 << "," << report.worst[0].y0;
}

TextureMap mapOf(int texture, TextureChannel channel) {
    TextureMap m;
    m.texture = texture;
    m.channel = channel;
    return m;
}

Texture checkerTexture() {
    Texture t;
    t.width = t.height = 64;
    t.channels = 3;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x)
            for (int c = 0; c < 3; ++c) t.texels.push_back(float(((x / 8) + (y / 8)) % 2));
    return t;
}

Texture rampTexture(int width, int height) {
    Texture t;
    t.colour = false;
    t.width = width;
    t.height = height;
    t.channels = 1;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) t.texels.push_back((x + 0.5f) / float(width));
    return t;
}

} // namespace pt::test
