// Camera rays of the lab's pinhole camera (vertical field of view), or of an orthographic one
// (glTF's), image row 0 at the top.
#pragma once

#include "accel/accel.h"
#include "scene/scene.h"

namespace pt {

class PinholeCamera {
public:
    PinholeCamera(const Camera& c, int width, int height) : origin_(c.position), width_(width), height_(height) {
        Vec3 forward = safeNormalize(c.target - c.position); // a plain length underflows at 1e-19
        Vec3 right = safeNormalize(glm::cross(forward, c.up)); // cameraup need not be orthogonal
        Vec3 up = glm::cross(right, forward);
        orthographic_ = c.orthoHalfHeight > 0.0f;
        float tanY = orthographic_ ? c.orthoHalfHeight : std::tan(glm::radians(0.5f * c.fovY));
        float tanX = tanY * float(width) / float(height);
        forward_ = forward;
        right_ = right * tanX;
        up_ = up * tanY;
    }

    // (px, py) in pixel units from the top-left corner of the image.
    Ray generate(float px, float py) const {
        float x = 2.0f * px / float(width_) - 1.0f;
        float y = 1.0f - 2.0f * py / float(height_);
        if (orthographic_) return Ray{origin_ + x * right_ + y * up_, forward_};
        return Ray{origin_, glm::normalize(forward_ + x * right_ + y * up_)};
    }

private:
    Vec3 origin_, forward_, right_, up_;
    int width_, height_;
    bool orthographic_ = false;
};

} // namespace pt
