#include "render/shading_triangles.h"

#include "core/ray_offset.h"

#include <algorithm>

namespace pt {

uint32_t encodeOctahedral(const Vec3& n) {
    float l1 = std::abs(n.x) + std::abs(n.y) + std::abs(n.z);
    float x = n.x / l1, y = n.y / l1;
    if (n.z < 0.0f) {
        float ox = (1.0f - std::abs(y)) * (x >= 0.0f ? 1.0f : -1.0f);
        float oy = (1.0f - std::abs(x)) * (y >= 0.0f ? 1.0f : -1.0f);
        x = ox;
        y = oy;
    }
    auto quantize = [](float v) { return uint32_t(std::lround((std::clamp(v, -1.0f, 1.0f) + 1.0f) * 0.5f * 65535.0f)); };
    return quantize(x) | (quantize(y) << 16);
}

std::vector<ShadingTriangle> buildShadingTriangles(const Scene& scene) {
    std::vector<ShadingTriangle> out(scene.triangleCount());
    for (size_t t = 0; t < out.size(); ++t) {
        const glm::uvec3& tri = scene.triPositions[t];
        const Vec3 &p0 = scene.positions[tri[0]], &p1 = scene.positions[tri[1]], &p2 = scene.positions[tri[2]];
        ShadingTriangle& s = out[t];
        s.p0 = p0;
        s.e1 = p1 - p0;
        s.e2 = p2 - p0;
        s.offsetError = triangleOffsetError(p0, p1, p2);
        s.materialAndFlags = scene.triMaterial[t];
        if (scene.triNormals.empty() || scene.triNormals[t].x < 0) continue; // the geometric normal
        // Vertex normals are normalized first, as other renderers do with OBJ normals.
        Vec3 n[3];
        bool usable = true;
        for (int k = 0; k < 3; ++k) {
            n[k] = scene.normals[scene.triNormals[t][k]];
            n[k] = safeNormalize(n[k]);
            usable &= n[k] != Vec3(0.0f);
        }
        if (!usable) continue;
        if (n[0] == n[1] && n[0] == n[2]) {
            s.materialAndFlags |= ShadingTriangle::kFlat;
            for (int k = 0; k < 3; ++k) s.flatNormal[k] = n[0][k];
        } else {
            s.materialAndFlags |= ShadingTriangle::kSmooth;
            for (int k = 0; k < 3; ++k) s.normals[k] = encodeOctahedral(n[k]);
        }
    }
    return out;
}

} // namespace pt
