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

void CameraController::reset() {
    frame_u_ = home_.u;
    frame_v_ = home_.v;
    frame_n_ = home_.n;
    // Orbit about the point straight ahead at the depth of the scene's middle.
    distance_ = std::max(glm::dot(scene_centre_ - home_.eye, -home_.n), 0.1f * scene_size_);
    yaw_ = pitch_ = 0.0f;
    target_ = home_.eye - distance_ * home_.n;
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
    constexpr float kMaxPitch = 1.55f;  // just short of straight up or down
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
    vec3 u = glm::cross(frame_v_, cam.n);
    if (glm::length(u) < 1e-6f) u = frame_u_;  // looking along the up axis
    cam.u = glm::normalize(u);
    cam.v = glm::cross(cam.n, cam.u);
    return cam.resized(std::max(1, cols), std::max(1, rows));
}

}  // namespace rt::viewer
