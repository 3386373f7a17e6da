#include "app/gl/shadow_maps.h"

#include <algorithm>

namespace rt::gl {
namespace {

// +x, -x, +y, -y, +z, -z, each with an up that is not along it.
const vec3 kAxes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
const vec3 kUps[6] = {{0, 1, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, 1}, {0, 1, 0}, {0, 1, 0}};

}  // namespace

Camera ShadowMaps::face_camera(const vec3& light, int face, int size) {
    return Camera::look_at(light, light + kAxes[face], kUps[face], 90.0f, size, size);
}

ShadowMaps::ShadowMaps(int light_count, int size) : asked_(size) {
    GLint most = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &most);
    lights_ = std::clamp(light_count, 1, kMaxLights);
    const int rows = std::min(kMaxAtlasRows, static_cast<int>(most));
    size_ = std::clamp(size, 16, std::min(rows / lights_, static_cast<int>(most) / 6));
    atlas_.emplace(Framebuffer::Kind::kDistance, 6 * size_, lights_ * size_);
    // Where a light-relative direction lands on each face: the face camera's matrices with
    // the light at the origin (x and y of clip space do not depend on near and far).
    for (int f = 0; f < 6; ++f) {
        const Camera c = face_camera(vec3(0.0f), f, size_);
        faces_[static_cast<std::size_t>(f)] = c.projection(0.1f, 10.0f) * c.view();
    }
}

}  // namespace rt::gl
