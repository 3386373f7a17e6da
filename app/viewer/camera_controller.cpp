#include "app/viewer/camera_controller.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace rt::viewer {

using rt::vec3;

CameraController::CameraController(const rt::Camera& home, const rt::Aabb& bounds)
    : home_(home),
      scene_size_(bounds.empty() ? 1.0f : std::max(glm::length(bounds.extent()), 1e-6f)),
      scene_centre_(bounds.empty() ? home.eye - home.n : bounds.centre()) {
    reset();
}

namespace {

// The world axis (+-x, +-y, +-z) nearest to v: a scene's up.
vec3 nearest_axis(const vec3& v) {
    int best = 0;
    for (int a = 1; a < 3; ++a)
        if (std::fabs(v[a]) > std::fabs(v[best])) best = a;
    vec3 axis(0.0f);
    axis[best] = v[best] < 0.0f ? -1.0f : 1.0f;
    return axis;
}

// u and v of a camera looking along -n with `up` as its up, turned by `roll` about n.
void frame_for(const vec3& n, const vec3& up, float roll, const vec3& fallback_u, vec3& u,
               vec3& v) {
    vec3 level = glm::cross(up, n);
    level = glm::length(level) < 1e-6f ? fallback_u : glm::normalize(level);
    const vec3 level_v = glm::cross(n, level);
    u = std::cos(roll) * level + std::sin(roll) * level_v;
    v = glm::cross(n, u);
}

}  // namespace

void CameraController::reset() {
    // Orbit about the point straight ahead at the depth of the scene's middle.
    distance_ = std::max(glm::dot(scene_centre_ - home_.eye, -home_.n), 0.1f * scene_size_);
    target_ = home_.eye - distance_ * home_.n;
    frame_v_ = nearest_axis(home_.v);
    const float elevation = glm::dot(home_.n, frame_v_);  // sin of the eye's pitch
    const vec3 horizontal = home_.n - elevation * frame_v_;
    frame_n_ = glm::length(horizontal) > 1e-6f ? glm::normalize(horizontal)
                                               : glm::normalize(glm::cross(home_.u, frame_v_));
    frame_u_ = glm::cross(frame_v_, frame_n_);
    yaw_ = 0.0f;
    pitch_ = std::asin(std::clamp(elevation, -1.0f, 1.0f));  // orbit() clamps it
    // The home camera's roll: the angle from the level u (no roll) to its own u, about n.
    vec3 level_u, level_v;
    frame_for(home_.n, frame_v_, 0.0f, frame_u_, level_u, level_v);
    roll_ = std::atan2(glm::dot(home_.u, level_v), glm::dot(home_.u, level_u));
    ++version_;
}

vec3 CameraController::offset() const {
    const float c = std::cos(pitch_);
    return distance_ * (c * std::sin(yaw_) * frame_u_ + std::sin(pitch_) * frame_v_ +
                        c * std::cos(yaw_) * frame_n_);
}

vec3 CameraController::eye() const { return target_ + offset(); }

void CameraController::orbit(float dx_pixels, float dy_pixels) {
    constexpr float kRadiansPerPixel = 0.006f;
    yaw_ -= dx_pixels * kRadiansPerPixel;
    pitch_ = std::clamp(pitch_ + dy_pixels * kRadiansPerPixel, -kMaxPitch, kMaxPitch);
    ++version_;
}

void CameraController::pan(float dx_pixels, float dy_pixels, int viewport_height) {
    const rt::Camera cam = camera(1, 1);
    // World units per pixel at the target's distance: the point under the cursor follows it.
    const float per_pixel =
        2.0f * distance_ * home_.H / home_.N / static_cast<float>(std::max(1, viewport_height));
    target_ += (-dx_pixels * cam.u + dy_pixels * cam.v) * per_pixel;
    ++version_;
}

void CameraController::zoom(float wheel_steps) {
    distance_ = std::max(distance_ * std::pow(0.85f, wheel_steps), 1e-4f * scene_size_);
    ++version_;
}

void CameraController::fly(const vec3& direction, float seconds, bool fast) {
    if (glm::length(direction) == 0.0f || seconds <= 0.0f) return;
    const rt::Camera cam = camera(1, 1);
    const float speed = 0.4f * scene_size_ * (fast ? 4.0f : 1.0f);
    target_ += (direction.x * cam.u + direction.y * cam.v - direction.z * cam.n) * speed * seconds;
    ++version_;
}

rt::Camera CameraController::camera(int cols, int rows) const {
    rt::Camera cam = home_;
    cam.eye = eye();
    cam.n = glm::normalize(offset());
    frame_for(cam.n, frame_v_, roll_, frame_u_, cam.u, cam.v);
    return cam.resized(std::max(1, cols), std::max(1, rows));
}

}  // namespace rt::viewer
