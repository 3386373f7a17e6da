// The raster's draw list (app/gl/gpu_scene.h) leaves out what a camera cannot see, and
// only that: no object it leaves out is met by any line of sight through the image, and
// a cube map's face, looking out from inside a crowd of objects, draws a fraction of them.
#include <gtest/gtest.h>

#include <cstdio>
#include <set>
#include <string>
#include <vector>

#include "app/gl/cube_atlas.h"
#include "app/gl/gpu_scene.h"
#include "core/scene.h"
#include "gl_fixture.h"

namespace rt {
namespace {

class GpuSceneGl : public GlTest {};

std::set<std::uint32_t> objects_drawn(gl::GpuScene& gpu, const Camera& camera,
                                      gl::GpuScene::Keep keep) {
    std::set<std::uint32_t> out;
    for (const gl::DrawItem& item : gpu.draw_list(camera, keep)) out.insert(item.object_id - 1);
    return out;
}

// The objects left out of the camera's draw list that a ray through the image meets:
// rays at 4 x 4 points of every pixel, edges and corners of the image included.
std::vector<std::uint32_t> left_out_but_seen(const Scene& scene, gl::GpuScene& gpu,
                                             const Camera& camera) {
    const std::set<std::uint32_t> kept = objects_drawn(gpu, camera, gl::GpuScene::Keep::kInView);
    std::vector<std::uint32_t> seen;
    for (std::uint32_t object = 0; object < scene.objects.size(); ++object) {
        if (kept.count(object) != 0) continue;
        bool met = false;
        for (int y = 0; y <= 4 * camera.rows && !met; ++y) {
            for (int x = 0; x <= 4 * camera.cols && !met; ++x) {
                Hit hit;
                met = scene.intersect_object(
                    object,
                    camera.ray_at(0.25f * static_cast<float>(x), 0.25f * static_cast<float>(y)),
                    hit);
            }
        }
        if (met) seen.push_back(object);
    }
    return seen;
}

// Each shipped scene from its own camera, and from the middle of its objects looking
// along the six axes (as an environment map's faces do): nothing left out is visible, and
// the six faces of a crowd draw not six times its objects but about once (many_spheres:
// 1,692 draws against 9,606 without leaving any out).
TEST_P(GpuSceneGl, TheDrawListLeavesOutWhatTheCameraCannotSeeAndOnlyThat) {
    for (const char* name : kScenes) {
        SCOPED_TRACE(name);
        const Scene scene(load(name, 32, 24));
        gl::GpuScene gpu(scene);
        EXPECT_EQ(left_out_but_seen(scene, gpu, scene.camera), std::vector<std::uint32_t>{});
        const Aabb box = scene.bounds();
        std::size_t kept = 0, all = 0;
        for (int face = 0; face < 6; ++face) {
            SCOPED_TRACE("face " + std::to_string(face));
            const Camera camera = gl::CubeAtlas::face_camera(box.centre(), face, 16);
            EXPECT_EQ(left_out_but_seen(scene, gpu, camera), std::vector<std::uint32_t>{});
            kept += gpu.draw_list(camera).size();
            all = gpu.draw_list(camera, gl::GpuScene::Keep::kAll).size();
        }
        std::printf("%s: six faces draw %zu items, each face without culling %zu\n", name, kept,
                    all);
        if (scene.objects.size() > 100) {
            EXPECT_LT(kept, 2 * all);
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Headless, GpuSceneGl, kBackends, backend_name);

}  // namespace
}  // namespace rt
