#pragma once
// The tutorial's pinhole camera: an eye, an orthonormal frame u, v, n (the camera looks
// along -n), a view plane of 2W x 2H at distance N, and nCols x nRows pixels.
// It owns both the traced rays and the raster matrices so the two cannot drift apart.

#include <glm/mat4x4.hpp>

#include "core/ray.h"

namespace rt {

struct Camera {
    vec3 eye{0.0f, 0.0f, 0.0f};
    vec3 u{1.0f, 0.0f, 0.0f};
    vec3 v{0.0f, 1.0f, 0.0f};
    vec3 n{0.0f, 0.0f, 1.0f};
    float W = 1.0f;  // half-width of the view plane
    float H = 1.0f;  // half-height of the view plane
    float N = 1.0f;  // distance from the eye to the view plane
    int cols = 640;
    int rows = 480;

    // A camera at `eye` looking at `target`, `up` giving the roll, with a vertical field
    // of view in degrees; W follows from the pixel aspect (square pixels).
    static Camera look_at(const vec3& eye, const vec3& target, const vec3& up, float vfov_degrees,
                          int cols, int rows);

    // The ray through the centre of pixel (x, y); y = 0 is the bottom row.
    // d = -N n + W (2(x + 1/2)/nCols - 1) u + H (2(y + 1/2)/nRows - 1) v
    Ray ray(int x, int y) const {
        return ray_at(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
    }
    // The same for a continuous position on the pixel grid.
    Ray ray_at(float px, float py) const { return Ray{eye, across(px) + upward(py)}; }
    // ray_at's direction as a term per column plus a term per row: the renderer computes
    // each once a tile and adds them per pixel, the same sum bit for bit.
    vec3 across(float px) const {  // -N n + W (2 px / nCols - 1) u
        return -N * n + W * (2.0f * px / static_cast<float>(cols) - 1.0f) * u;
    }
    vec3 upward(float py) const {  // H (2 py / nRows - 1) v
        return H * (2.0f * py / static_cast<float>(rows) - 1.0f) * v;
    }

    // The same camera for the raster pipeline: view = the (u, v, n, eye) frame,
    // projection = glFrustum(-W, W, -H, H, N, far).
    glm::mat4 view() const;
    glm::mat4 projection(float far_plane) const;
    // The same frustum cut at another near plane: scaling -W, W, -H, H by near / N keeps
    // every pixel's line of sight, so only depth clipping changes.
    glm::mat4 projection(float near_plane, float far_plane) const;

    // The same view with another resolution: keeps N and H, sets W for square pixels.
    Camera resized(int new_cols, int new_rows) const;

    bool operator==(const Camera&) const = default;
};

}  // namespace rt
