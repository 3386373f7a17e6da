#include "core/camera.h"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace rt {

Camera Camera::look_at(const vec3& eye, const vec3& target, const vec3& up, float vfov_degrees,
                       int cols, int rows) {
    Camera cam;
    cam.eye = eye;
    cam.n = glm::normalize(eye - target);
    cam.u = glm::normalize(glm::cross(up, cam.n));
    cam.v = glm::cross(cam.n, cam.u);
    cam.N = 1.0f;
    cam.H = cam.N * std::tan(glm::radians(vfov_degrees) * 0.5f);
    cam.cols = cols;
    cam.rows = rows;
    cam.W = cam.H * static_cast<float>(cols) / static_cast<float>(rows);
    return cam;
}

glm::mat4 Camera::view() const {
    glm::mat4 m(1.0f);
    for (int c = 0; c < 3; ++c) {  // rows of the rotation are u, v, n
        m[c][0] = u[c];
        m[c][1] = v[c];
        m[c][2] = n[c];
    }
    m[3][0] = -glm::dot(u, eye);
    m[3][1] = -glm::dot(v, eye);
    m[3][2] = -glm::dot(n, eye);
    return m;
}

glm::mat4 Camera::projection(float far_plane) const {
    return glm::frustum(-W, W, -H, H, N, far_plane);
}

glm::mat4 Camera::projection(float near_plane, float far_plane) const {
    const float k = near_plane / N;
    return glm::frustum(-W * k, W * k, -H * k, H * k, near_plane, far_plane);
}

Camera Camera::resized(int new_cols, int new_rows) const {
    Camera cam = *this;
    cam.cols = new_cols;
    cam.rows = new_rows;
    cam.W = H * static_cast<float>(new_cols) / static_cast<float>(new_rows);
    return cam;
}

}  // namespace rt
