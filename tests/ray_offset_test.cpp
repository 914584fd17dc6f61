// Rays leaving a surface must not hit it again, at any scale and any distance from the origin:
// the offset comes from an error bound, not an epsilon (cf. pbrt's Triangle.Reintersect).
#include "accel/accel.h"
#include "core/ray_offset.h"
#include "render/surface_hit.h"
#include "sampling/rng.h"
#include "sampling/warp.h"
#include "tests/test_scenes.h"

#include <gtest/gtest.h>

namespace pt::test {
namespace {

// Triangle shapes that stress different parts of the intersector's arithmetic.
enum class Shape { Random, AxisAligned, Sliver, Large };

TEST(RayOffset, NoSelfIntersectionAtAnyScale) {
    Pcg32 rng(42, 7);
    auto uniform = [&](float lo, float hi) { return lo + (hi - lo) * rng.nextFloat(); };
    int failures = 0, trials = 0;
    std::string firstFailure;
    for (Shape shape : {Shape::Random, Shape::AxisAligned, Shape::Sliver, Shape::Large})
        for (float scale : {1e-4f, 1e-3f, 1.0f, 1e3f, 1e4f})
            for (float offset : {0.0f, 1.0f, 1e4f})
                for (int tri = 0; tri < 12; ++tri) {
                    Scene scene;
                    Material m;
                    uint32_t mat = addMaterial(scene, m);
                    Vec3 translate = offset * scale * glm::normalize(Vec3(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)));
                    if (shape == Shape::AxisAligned && tri % 2 == 0) translate = Vec3(0.0f); // a plane through 0
                    auto corner = [&] {
                        Vec3 c(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
                        if (shape == Shape::AxisAligned) c[tri % 3] = 0.0f;
                        if (shape == Shape::Large) c *= 100.0f;
                        return translate + scale * c;
                    };
                    Vec3 a = corner(), b = corner(), c = corner();
                    if (shape == Shape::Sliver) c = a + 1e-3f * (c - a) + 0.999f * (b - a);
                    addTriangle(scene, a, b, c, mat);
                    Accel accel(scene, 1);
                    std::vector<ShadingTriangle> shading = buildShadingTriangles(scene);
                    for (int i = 0; i < 100; ++i) {
                        Hit hit;
                        hit.prim = 0;
                        hit.u = rng.nextFloat();
                        hit.v = rng.nextFloat() * (1.0f - hit.u);
                        SurfacePoint sp = makeSurfacePoint(shading[0], hit);
                        Vec3 dir = squareToUniformSphere(Vec2(rng.nextFloat(), rng.nextFloat()));
                        if (std::abs(glm::dot(dir, sp.ng)) < 1e-3f) continue; // grazing: either side is fine
                        Ray ray = spawnRay(sp, dir);
                        ++trials;
                        Hit again = accel.intersect(ray);
                        if (again.found()) {
                            if (failures++ == 0)
                                firstFailure = "shape " + std::to_string(int(shape)) + " scale " + std::to_string(scale) +
                                               " offset " + std::to_string(offset) + " t " + std::to_string(again.t);
                        }
                    }
                }
    EXPECT_EQ(failures, 0) << "of " << trials << " rays; first: " << firstFailure;
}

// The offset stays tiny relative to the coordinates, so contact shadows survive.
TEST(RayOffset, OffsetIsAFewUlps) {
    Vec3 p(1000.0f, 2.0f, -3.0f);
    float err = triangleOffsetError(p, p + Vec3(0.5f, 0, 0), p + Vec3(0, 0.5f, 0));
    Vec3 o = offsetRayOrigin(p, err, Vec3(1, 0, 0), Vec3(1, 0, 0));
    EXPECT_GT(o.x, p.x);
    EXPECT_LT(o.x - p.x, 1000.0f * 1e-5f);
    EXPECT_EQ(o.y, p.y);
    Vec3 below = offsetRayOrigin(p, err, Vec3(0, 1, 0), Vec3(0.5f, -1, 0)); // leaving the other side
    EXPECT_LT(below.y, p.y);
    EXPECT_GT(below.y, p.y - 1000.0f * 1e-5f);
}

} // namespace
} // namespace pt::test
