#include "tests/scene_builders.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

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

void addUvQuad(Scene& scene, Vec3 a, Vec3 b, Vec3 c, Vec3 d, uint32_t material, Vec2 uv0, Vec2 uv1,
               Vec3 normal) {
    size_t before = scene.triangleCount();
    addQuad(scene, a, b, c, d, material);
    scene.triUvs.resize(before, glm::ivec3(-1));
    int base = int(scene.uvs.size());
    scene.uvs.insert(scene.uvs.end(), {uv0, Vec2(uv1.x, uv0.y), uv1, Vec2(uv0.x, uv1.y)});
    scene.triUvs.emplace_back(base, base + 1, base + 2);
    scene.triUvs.emplace_back(base, base + 2, base + 3);
    if (normal != Vec3(0.0f)) {
        scene.triNormals.resize(before, glm::ivec3(-1));
        int n = int(scene.normals.size());
        scene.normals.push_back(normal);
        scene.triNormals.emplace_back(n);
        scene.triNormals.emplace_back(n);
    }
    if (!scene.triNormals.empty()) scene.triNormals.resize(scene.triangleCount(), glm::ivec3(-1));
}

Material lambert(Spectrum kd) {
    Material m;
    m.kd = kd;
    return m;
}

std::vector<std::pair<std::string, Material>> labMaterials() {
    std::vector<std::pair<std::string, Material>> out;
    out.emplace_back("lambert", lambert(Spectrum(0.5f, 0.7f, 0.9f)));
    Material mirror;
    mirror.kd = Spectrum(0.0f);
    mirror.blend = 1.0f;
    mirror.r0 = Spectrum(1.0f);
    mirror.ks = Spectrum(0.9f);
    out.emplace_back("mirror", mirror);
    Material glass;
    glass.blend = 1.0f;
    glass.r0 = Spectrum(0.04f);
    glass.transparency = 1.0f;
    glass.eta = 1.5f;
    out.emplace_back("glass", glass);
    Material plastic; // Fresnel blend of a mirror over Lambert (cornellbottle2's walls)
    plastic.kd = Spectrum(0.75f, 0.3f, 0.3f);
    plastic.blend = 1.0f;
    plastic.r0 = Spectrum(0.1f);
    out.emplace_back("plastic", plastic);
    Material mixed; // every lobe at once, linear blend w = 0.5
    mixed.kd = Spectrum(0.6f);
    mixed.blend = 0.5f;
    mixed.r0 = Spectrum(0.2f, 0.3f, 0.4f);
    mixed.transparency = 0.3f;
    mixed.eta = 1.33f;
    out.emplace_back("mixed", mixed);
    return out;
}

Material labMaterial(const std::string& name) {
    for (auto& [n, m] : labMaterials())
        if (n == name) return m;
    throw std::invalid_argument("no lab material " + name);
}

} // namespace pt::test
