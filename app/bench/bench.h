#pragma once
// rtbench's pieces: the triangles every structure is given, the ray sets every structure
// traces, and the structures themselves behind one small interface, so that ours and
// Intel Embree see the same triangles, the same rays and the same threads.

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include "app/gl/context.h"

#include "core/accel.h"
#include "core/mesh.h"
#include "core/scene.h"
#include "core/tracer.h"

namespace rt::bench {

using rt::vec3;

// The scene as world-space triangles: meshes and triangles as they are, spheres
// tessellated (96 slices); planes, being infinite, are left out.
rt::TriangleMesh flatten(const rt::SceneDescription& scene);

struct RaySet {
    std::string name;  // primary, shadow, secondary, mirror
    std::vector<rt::Ray> rays;
    std::vector<float> t_max;
    bool occlusion = false;  // any-hit queries (shadow feelers)
};

struct Result {  // of one ray
    float t = rt::kInfinity;
    std::uint32_t prim = ~0u;
    bool hit() const { return t < rt::kInfinity; }
};

// One ray through each pixel's centre, row by row: the primary rays every mode traces.
RaySet primary_rays(const rt::Camera& camera);

// Coherent primary rays from `camera`; shadow feelers from their hits to every light;
// incoherent secondary rays, cosine-distributed about the hit normals (seeded, so every
// run and every structure gets the same rays), as a path tracer's diffuse bounces; and
// the primary rays mirrored at their hits, the secondary rays a Whitted tracer makes
// (reflections: neighbours' rays leave nearby points in nearby directions, as the
// renderer's bounces do, which it traces in packets).
std::vector<RaySet> make_ray_sets(const rt::Camera& camera, const rt::TriangleMesh& mesh,
                                  const std::vector<rt::Light>& lights,
                                  const std::vector<Result>& primary_hits);

class Structure {
  public:
    virtual ~Structure() = default;
    virtual std::string name() const = 0;
    virtual void prepare(const rt::TriangleMesh& mesh) = 0;  // copies the triangles in: not timed
    virtual void build() = 0;                                // the structure itself: timed
    virtual std::size_t memory_bytes() const = 0;
    virtual Result intersect(const rt::Ray& ray, float t_max) const = 0;
    virtual bool occluded(const rt::Ray& ray, float t_max) const = 0;
    // A structure that traces packets (`packets()`) gets the rays kPacketWidth at a
    // time: rays[0, count) with their t_max, answers into out[0, count).
    virtual bool packets() const { return false; }
    virtual void intersect_packet(const rt::Ray* rays, const float* t_max, int count,
                                  Result* out) const {
        for (int i = 0; i < count; ++i) out[i] = intersect(rays[i], t_max[i]);
    }
    virtual void occluded_packet(const rt::Ray* rays, const float* t_max, int count,
                                 Result* out) const {
        for (int i = 0; i < count; ++i)
            out[i].t = occluded(rays[i], t_max[i]) ? 0.0f : rt::kInfinity;
    }
    // A structure that answers a whole set at once (the GPU): answers every stride-th ray
    // of `set` and returns the seconds the tracing itself took (the rays already up, the
    // answers not yet read back). Nothing for those that answer a ray at a time.
    virtual std::optional<double> trace_set(const RaySet& /*set*/, std::size_t /*stride*/,
                                            std::vector<Result>& /*answers*/) const {
        return std::nullopt;
    }
};

// Builds on `threads` threads, as Embree's device does with its own. `packets`: traces
// kPacketWidth rays at a time (our wide BVH's packet traversal; Embree's rtcIntersect8 /
// rtcOccluded8, or 4 where our packets are 4 wide), named "bvh-packets",
// "embree-packets".
std::unique_ptr<Structure> make_ours(rt::AccelKind kind, int threads, bool packets = false);
std::unique_ptr<Structure> make_embree(int threads,
                                       bool packets = false);  // nullptr without Embree
// Embree with RTC_SCENE_FLAG_ROBUST ("embree-robust"): watertight and conservative, as
// ours are; a comparison point beside the default's, never the reference.
std::unique_ptr<Structure> make_embree_robust(int threads);  // nullptr without Embree
bool have_embree();
// The GPU tracer's traversal (app/gl/gpu_tracer.h) on a headless context of `backend`:
// throws rt::Error where there is no context or no compute shaders.
std::unique_ptr<Structure> make_gpu(rt::gl::Backend backend);
// A whole frame of the scene (not its triangles alone: spheres, planes, materials) traced
// by the GPU tracer at `camera`, on the current context: the median of `repeats`
// dispatches after a warm-up, and how far its image is from the CPU tracer's (on
// `threads` threads), as JSON and printed.
nlohmann::json time_gpu_frame(const rt::SceneDescription& scene, const rt::Camera& camera,
                              const rt::TraceOptions& options, int repeats, int threads);

// Runs body(begin, end) over [0, count) in chunks on `threads` threads.
void parallel_for(std::size_t count, int threads,
                  const std::function<void(std::size_t, std::size_t)>& body);

double median(std::vector<double> values);

}  // namespace rt::bench
