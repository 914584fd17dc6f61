// Accel's answers against a brute-force loop: sphere lights live in Embree as a user geometry, so
// the BVH, the packet path and the shadow query's skip of the light being sampled must each give
// exactly what testing every sphere would.
#include "accel/accel.h"
#include "sampling/rng.h"
#include "sampling/warp.h"
#include "tests/test_scenes.h"

#include <gtest/gtest.h>

namespace pt::test {
namespace {

// A floor at y = -1 (two triangles, [-3, 3]^2) and `count` sphere lights of radii 1e-3 to 0.3, with
// point lights (which are not geometry) mixed into Scene::lights so that indices must map. 300
// puts the spheres into the BVH, 8 (7 spheres and a point) leaves them to the loop after it.
const int kCounts[] = {300, 8};

Scene sphereField(Pcg32& rng, int count) {
    Scene scene;
    uint32_t m = addMaterial(scene, Material{});
    addQuad(scene, {-3, -1, -3}, {3, -1, -3}, {3, -1, 3}, {-3, -1, 3}, m);
    for (int i = 0; i < count; ++i) {
        LocalLight l;
        l.center = Vec3(rng.nextFloat(), rng.nextFloat(), rng.nextFloat()) * 4.0f - 2.0f;
        l.radius = i % 7 == 0 ? 0.0f : std::pow(10.0f, -3.0f + 2.5f * rng.nextFloat());
        scene.lights.push_back(l);
    }
    return scene;
}

struct Expected {
    float t = kInf;
    uint32_t light = Hit::kNone; // Scene::lights index, or kNone for the floor or nothing
};

Expected bruteForce(const Scene& scene, const Ray& ray, int skipLight = -1) {
    Expected e;
    if (ray.dir.y != 0.0f) { // the floor
        float t = (-1.0f - ray.origin.y) / ray.dir.y;
        Vec3 p = ray.origin + t * ray.dir;
        if (t > 0.0f && std::abs(p.x) <= 3.0f && std::abs(p.z) <= 3.0f) e.t = t;
    }
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        const LocalLight& l = scene.lights[i];
        if (l.isPoint() || int(i) == skipLight) continue;
        float t = intersectSphere(ray.origin, ray.dir, l.center, l.radius);
        if (t < e.t) e = {t, uint32_t(i)};
    }
    return e;
}

void expectHit(const Hit& hit, const Expected& e, int ray) {
    if (e.light != Hit::kNone) {
        ASSERT_TRUE(hit.onSphere) << "ray " << ray << ": expected sphere light " << e.light << " at t " << e.t;
        EXPECT_EQ(hit.prim, e.light) << "ray " << ray;
        EXPECT_EQ(hit.t, e.t) << "ray " << ray; // the same exact test, so the same float
    } else if (e.t < kInf) {
        ASSERT_TRUE(hit.found() && !hit.onSphere) << "ray " << ray << ": expected the floor at t " << e.t;
        EXPECT_NEAR(hit.t, e.t, 1e-4f * e.t) << "ray " << ray;
    } else {
        EXPECT_FALSE(hit.found()) << "ray " << ray << ": expected a miss, got t " << hit.t;
    }
}

TEST(Accel, SphereLightsAnswerAsTestingEverySphere) {
    for (int count : kCounts) {
        SCOPED_TRACE(std::to_string(count) + " lights");
        Pcg32 rng(3, 11);
        Scene scene = sphereField(rng, count);
        Accel accel(scene, 1);
        int sphereHits = 0;
        for (int i = 0; i < 20000; ++i) {
            Vec3 o = Vec3(rng.nextFloat(), rng.nextFloat(), rng.nextFloat()) * 5.0f - 2.5f;
            Ray ray{o, squareToUniformSphere(Vec2(rng.nextFloat(), rng.nextFloat()))};
            Expected e = bruteForce(scene, ray);
            sphereHits += e.light != Hit::kNone;
            expectHit(accel.intersect(ray), e, i);
            if (::testing::Test::HasFailure()) return;
        }
        EXPECT_GT(sphereHits, count > 100 ? 2000 : 10); // the spheres must be exercised, not only the floor
    }
}

TEST(Accel, CameraPacketsAnswerAsSingleRays) {
    for (int count : kCounts) {
        SCOPED_TRACE(std::to_string(count) + " lights");
        Pcg32 rng(5, 11);
        Scene scene = sphereField(rng, count);
        Accel accel(scene, 1);
        for (int packet = 0; packet < 2000; ++packet) {
            Ray rays[Accel::kPacket];
            bool active[Accel::kPacket];
            Vec3 o = Vec3(rng.nextFloat(), rng.nextFloat(), rng.nextFloat()) * 5.0f - 2.5f;
            for (int i = 0; i < Accel::kPacket; ++i) {
                rays[i] = Ray{o, squareToUniformSphere(Vec2(rng.nextFloat(), rng.nextFloat()))};
                active[i] = rng.nextFloat() < 0.8f;
            }
            int count = 1 + int(rng.nextUint() % Accel::kPacket);
            Hit hits[Accel::kPacket];
            for (Hit& h : hits) h.t = -1.0f; // lanes left alone keep this
            accel.intersectCameraRays(rays, active, count, hits);
            for (int i = 0; i < Accel::kPacket; ++i) {
                if (i < count && active[i]) expectHit(hits[i], bruteForce(scene, rays[i]), packet * 8 + i);
                else EXPECT_EQ(hits[i].t, -1.0f) << "inactive lane " << i << " was written";
            }
            if (::testing::Test::HasFailure()) return;
        }
    }
}

TEST(Accel, ShadowRaysSkipOnlyTheLightAimedAt) {
    for (int count : kCounts) {
        SCOPED_TRACE(std::to_string(count) + " lights");
        Pcg32 rng(7, 11);
        Scene scene = sphereField(rng, count);
        Accel accel(scene, 1);
        int blocked = 0, trials = 0;
        for (int i = 0; i < 20000; ++i) {
            Vec3 o = Vec3(rng.nextFloat(), rng.nextFloat(), rng.nextFloat()) * 5.0f - 2.5f;
            Ray ray{o, squareToUniformSphere(Vec2(rng.nextFloat(), rng.nextFloat()))};
            int skip = rng.nextFloat() < 0.5f ? -1 : int(rng.nextUint() % scene.lights.size());
            // Aim at the skipped light when there is one to aim at: the common case in the path loop.
            if (skip >= 0 && !scene.lights[size_t(skip)].isPoint())
                ray.dir = glm::normalize(scene.lights[size_t(skip)].center - o);
            float tfar = 0.1f + 4.0f * rng.nextFloat();
            Expected e = bruteForce(scene, ray, skip);
            // Ties within a float of tfar are either answer.
            if (std::abs(e.t - tfar) < 1e-5f * tfar) continue;
            bool expected = e.t < tfar;
            ++trials;
            blocked += expected;
            ASSERT_EQ(accel.occluded(ray, tfar, skip), expected) << "ray " << i << " skip " << skip << " tfar " << tfar
                                                                 << " nearest " << e.t;
        }
        EXPECT_GT(blocked, trials / 10);
        EXPECT_LT(blocked, trials - trials / 10);
    }
}

} // namespace
} // namespace pt::test
