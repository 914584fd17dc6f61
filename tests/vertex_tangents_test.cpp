// Per-vertex tangents for normal maps (MikkTSpace's rules): the tangent follows increasing u,
// sign * cross(n, t) follows increasing v whichever way the uv layout is mirrored, tangents are
// orthogonal to the vertex normal, shared vertices agree, and scenes without normal maps get none.
#include "render/vertex_tangents.h"

#include <gtest/gtest.h>

namespace pt {
namespace {

// A quad in the plane y = 0 from x, z in [-1, 1], u along `uDir` and v along `vDir` (unit axes).
Scene uvQuad(Vec3 uDir, Vec3 vDir, bool normalMap = true) {
    Scene s;
    Material m;
    if (normalMap) m.normalMap.texture = 0;
    s.materials.push_back(m);
    Vec3 corners[4] = {{-1, 0, 1}, {1, 0, 1}, {1, 0, -1}, {-1, 0, -1}};
    for (Vec3 p : corners) {
        s.positions.push_back(p);
        s.uvs.push_back(Vec2(0.5f + 0.5f * glm::dot(p, uDir), 0.5f + 0.5f * glm::dot(p, vDir)));
    }
    s.normals.push_back(Vec3(0, 1, 0));
    s.triPositions = {{0, 1, 2}, {0, 2, 3}};
    s.triUvs = {{0, 1, 2}, {0, 2, 3}};
    s.triNormals = {{0, 0, 0}, {0, 0, 0}};
    s.triMaterial = {0, 0};
    return s;
}

void expectVec(Vec3 got, Vec3 want, const char* what) {
    EXPECT_NEAR(got.x, want.x, 1e-5f) << what;
    EXPECT_NEAR(got.y, want.y, 1e-5f) << what;
    EXPECT_NEAR(got.z, want.z, 1e-5f) << what;
}

TEST(VertexTangents, FollowUAndVForEveryMirroring) {
    const Vec3 n(0, 1, 0);
    struct Case {
        Vec3 u, v;
        float sign;
        const char* what;
    } cases[] = {{{1, 0, 0}, {0, 0, -1}, 1.0f, "u along +x, v along -z"},
                 {{-1, 0, 0}, {0, 0, -1}, -1.0f, "u mirrored"},
                 {{1, 0, 0}, {0, 0, 1}, -1.0f, "v mirrored"},
                 {{0, 0, 1}, {1, 0, 0}, 1.0f, "rotated a quarter turn"}};
    for (const Case& c : cases) {
        std::vector<CornerTangent> t = buildCornerTangents(uvQuad(c.u, c.v));
        ASSERT_EQ(t.size(), 6u);
        for (const CornerTangent& k : t) {
            expectVec(k.tangent, c.u, c.what);
            EXPECT_EQ(k.sign, c.sign) << c.what;
            expectVec(k.sign * glm::cross(n, k.tangent), c.v, c.what);
        }
    }
}

TEST(VertexTangents, NoneWithoutNormalMaps) {
    EXPECT_TRUE(buildCornerTangents(uvQuad({1, 0, 0}, {0, 0, -1}, false)).empty());
}

// Two faces folded along a shared edge, with the vertex normals of a smooth crease: the shared
// vertices' tangents are one vector (both faces' tangents summed), orthogonal to their normal.
TEST(VertexTangents, SharedVerticesAgreeAndAreOrthogonalToTheirNormal) {
    Scene s;
    Material m;
    m.normalMap.texture = 0;
    s.materials.push_back(m);
    // Edge from (0,0,0) to (0,0,-1); one face leans to -x, the other to +x, tilted up.
    s.positions = {{0, 0, 0}, {0, 0, -1}, {-1, -0.3f, 0}, {1, -0.3f, 0}, {-1, -0.3f, -1}, {1, -0.3f, -1}};
    s.uvs = {{0.5f, 0}, {0.5f, 1}, {0, 0}, {1, 0}, {0, 1}, {1, 1}};
    Vec3 left = glm::normalize(Vec3(-0.3f, 1, 0)), right = glm::normalize(Vec3(0.3f, 1, 0));
    s.normals = {Vec3(0, 1, 0), left, right};
    s.triPositions = {{2, 0, 1}, {2, 1, 4}, {0, 3, 5}, {0, 5, 1}};
    s.triUvs = {{2, 0, 1}, {2, 1, 4}, {0, 3, 5}, {0, 5, 1}}; // as the positions
    s.triNormals = {{1, 0, 0}, {1, 0, 1}, {0, 2, 2}, {0, 2, 0}};
    s.triMaterial = {0, 0, 0, 0};
    std::vector<CornerTangent> t = buildCornerTangents(s);
    ASSERT_EQ(t.size(), 12u);
    for (size_t tri = 0; tri < 4; ++tri)
        for (int k = 0; k < 3; ++k) {
            const CornerTangent& c = t[3 * tri + k];
            Vec3 n = glm::normalize(s.normals[s.triNormals[tri][k]]);
            EXPECT_NEAR(glm::dot(c.tangent, n), 0.0f, 1e-5f);
            EXPECT_NEAR(glm::length(c.tangent), 1.0f, 1e-5f);
            EXPECT_GT(c.tangent.x, 0.9f) << "u increases along +x on both faces";
            EXPECT_EQ(c.sign, 1.0f);
        }
    // Vertex 0 (position 0, normal 0, uv 0) is shared by three corners: one tangent for all.
    expectVec(t[1].tangent, t[6].tangent, "shared vertex");
    expectVec(t[1].tangent, t[9].tangent, "shared vertex");
    expectVec(t[1].tangent, Vec3(1, 0, 0), "the crease's tangents average to +x");
}

} // namespace
} // namespace pt
