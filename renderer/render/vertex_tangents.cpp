#include "render/vertex_tangents.h"

#include <algorithm>
#include <unordered_map>

namespace pt {
namespace {

// A vertex as MikkTSpace welds them: position, normal, uv, and the handedness of the faces.
struct VertexKey {
    uint32_t position;
    int normal, uv;
    bool positive;
    bool operator==(const VertexKey& o) const {
        return position == o.position && normal == o.normal && uv == o.uv && positive == o.positive;
    }
};
struct VertexKeyHash {
    size_t operator()(const VertexKey& k) const {
        uint64_t h = uint64_t(k.position) * 0x9E3779B97F4A7C15ull;
        h ^= (uint64_t(uint32_t(k.normal)) + 0x632BE59BD9B4E019ull + (h << 6) + (h >> 2));
        h ^= (uint64_t(uint32_t(k.uv)) * 2 + k.positive + 0x85EBCA77C2B2AE63ull + (h << 6) + (h >> 2));
        return size_t(h);
    }
};

Vec3 projectOut(const Vec3& v, const Vec3& n) { return v - n * glm::dot(n, v); }

} // namespace

std::vector<CornerTangent> buildCornerTangents(const Scene& scene) {
    bool needed = false;
    for (const Material& m : scene.materials) needed |= m.normalMap.used();
    if (!needed || scene.triUvs.empty()) return {}; // without uvs no map is read

    const size_t count = scene.triangleCount();
    std::vector<CornerTangent> corners(3 * count);
    std::vector<VertexKey> keys(3 * count);
    std::vector<Vec3> faceTangent(count, Vec3(0.0f)), cornerNormal(3 * count);
    std::unordered_map<VertexKey, Vec3, VertexKeyHash> sums;

    for (size_t t = 0; t < count; ++t) {
        const glm::ivec3& ti = scene.triUvs[t];
        if (!scene.materials[scene.triMaterial[t]].normalMap.used() || ti.x < 0) continue;
        const glm::uvec3& pi = scene.triPositions[t];
        Vec3 p[3] = {scene.positions[pi[0]], scene.positions[pi[1]], scene.positions[pi[2]]};
        Vec2 uv[3] = {scene.uvs[ti[0]], scene.uvs[ti[1]], scene.uvs[ti[2]]};
        Vec3 d1 = p[1] - p[0], d2 = p[2] - p[0];
        Vec2 s1 = uv[1] - uv[0], s2 = uv[2] - uv[0];
        Vec3 dpdu, dpdv;
        float area2 = uvDerivatives(d1, d2, s1, s2, dpdu, dpdv); // its sign is the handedness
        if (area2 == 0.0f) continue;
        bool positive = area2 > 0.0f;
        Vec3 ng = safeNormalize(glm::cross(d1, d2));
        bool hasNormals = !scene.triNormals.empty() && scene.triNormals[t].x >= 0;
        for (int k = 0; k < 3; ++k) {
            Vec3 n = hasNormals ? safeNormalize(scene.normals[scene.triNormals[t][k]]) : ng;
            if (n == Vec3(0.0f)) n = ng;
            size_t c = 3 * t + k;
            cornerNormal[c] = n;
            keys[c] = VertexKey{pi[k], hasNormals ? scene.triNormals[t][k] : -1, ti[k], positive};
            corners[c].sign = positive ? 1.0f : -1.0f;
            // The corner's angle, measured in the plane of its normal, weighs this face's tangent.
            Vec3 a = safeNormalize(projectOut(p[(k + 1) % 3] - p[k], n));
            Vec3 b = safeNormalize(projectOut(p[(k + 2) % 3] - p[k], n));
            float angle = std::acos(std::clamp(glm::dot(a, b), -1.0f, 1.0f));
            Vec3 tangent = safeNormalize(projectOut(dpdu, n));
            sums[keys[c]] += angle * tangent;
        }
        faceTangent[t] = dpdu;
    }
    for (size_t t = 0; t < count; ++t) {
        if (faceTangent[t] == Vec3(0.0f)) continue;
        for (int k = 0; k < 3; ++k) {
            size_t c = 3 * t + k;
            Vec3 sum = sums[keys[c]];
            // Faces whose tangents cancel at a vertex: fall back to this face's own.
            if (safeLength(sum) < 1e-6f) sum = projectOut(faceTangent[t], cornerNormal[c]);
            corners[c].tangent = safeNormalize(sum);
        }
    }
    // Tangents the file gives (glTF's TANGENT) replace generated ones: the normal map was baked
    // against them, with bitangent = w cross(n, t) as pt's sign has it.
    if (!scene.vertexTangents.empty())
        for (size_t t = 0; t < count; ++t) {
            if (!scene.materials[scene.triMaterial[t]].normalMap.used()) continue;
            for (int k = 0; k < 3; ++k) {
                const glm::vec4& given = scene.vertexTangents[scene.triPositions[t][k]];
                if (given.w != 0.0f) corners[3 * t + k] = CornerTangent{Vec3(given), given.w};
            }
        }
    return corners;
}

} // namespace pt
