#pragma once
// The viewer's camera: orbit about a target, pan, zoom, and WASD/QE flight, turned into
// the tutorial's Camera for any window size. No GL, no window: unit-tested alone.
//
// Orbit is a turntable: yaw about the scene's up axis (the world axis nearest the home
// camera's v), pitch about the camera's right axis, stopped short of the poles, so the
// horizon never rolls. A home camera with a roll of its own keeps that roll, unchanged.

#include <cstdint>

#include "core/aabb.h"
#include "core/camera.h"

namespace rt::viewer {

class CameraController {
  public:
    static constexpr float kMaxPitch = 1.5f;  // radians above or below the horizon (86 degrees)

    // Starts at `home` (the scene's camera), looking at the middle of `bounds`.
    CameraController(const rt::Camera& home, const rt::Aabb& bounds);

    void reset();
    void orbit(float dx_pixels, float dy_pixels);
    void pan(float dx_pixels, float dy_pixels, int viewport_height);
    void zoom(float wheel_steps);  // positive: closer
    // Moves eye and target: x right, y up, z forward, for `seconds`; `fast` is Shift.
    void fly(const rt::vec3& direction, float seconds, bool fast);

    rt::Camera camera(int cols, int rows) const;
    std::uint64_t version() const { return version_; }  // changes whenever the camera does
    rt::vec3 eye() const;
    rt::vec3 target() const { return target_; }

  private:
    rt::vec3 offset() const;  // eye - target

    rt::Camera home_;
    float scene_size_;
    rt::vec3 scene_centre_;
    rt::vec3 target_{0.0f};
    // The turntable's frame: v the scene's up axis, n the home view direction made
    // horizontal (reversed: the eye's side), u = v x n.
    rt::vec3 frame_u_{1, 0, 0}, frame_v_{0, 1, 0}, frame_n_{0, 0, 1};
    float yaw_ = 0.0f, pitch_ = 0.0f, distance_ = 1.0f;
    float roll_ = 0.0f;  // the home camera's own roll about n, kept
    std::uint64_t version_ = 0;
};

}  // namespace rt::viewer
