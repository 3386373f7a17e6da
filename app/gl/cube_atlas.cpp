#include "app/gl/cube_atlas.h"

#include <algorithm>

namespace rt::gl {
namespace {

// +x, -x, +y, -y, +z, -z, each with an up that is not along it.
const vec3 kAxes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
const vec3 kUps[6] = {{0, 1, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, 1}, {0, 1, 0}, {0, 1, 0}};

}  // namespace

Camera CubeAtlas::face_camera(const vec3& centre, int face, int size) {
    return Camera::look_at(centre, centre + kAxes[face], kUps[face], 90.0f, size, size);
}

CubeAtlas::CubeAtlas(Framebuffer::Kind kind, int rows, int size) : asked_(size) {
    GLint most = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &most);
    rows_ = std::clamp(rows, 1, kMaxRows);
    const int texels = std::min(kMaxAtlasRows, static_cast<int>(most));
    size_ = std::clamp(size, 16, std::min(texels / rows_, static_cast<int>(most) / 6));
    atlas_.emplace(kind, 6 * size_, rows_ * size_);
    // Where a direction from the centre lands on each face: the face camera's matrices with
    // the centre at the origin (x and y of clip space do not depend on near and far).
    for (int f = 0; f < 6; ++f) {
        const Camera c = face_camera(vec3(0.0f), f, size_);
        faces_[static_cast<std::size_t>(f)] = c.projection(0.1f, 10.0f) * c.view();
    }
}

}  // namespace rt::gl
