#pragma once
// The third pipeline: core's Whitted tracer run on the GPU as an OpenGL 4.3 compute shader
// (shaders/gputrace.comp), one invocation per pixel. The scene goes up once, as the
// flat arrays of core/flat_scene.h in shader storage buffers; each frame is then one
// dispatch and, for an rt::Image, one read-back. docs/gpu-tracer.md says what it does
// and where it differs from the CPU tracer.

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "app/gl/handle.h"
#include "app/gl/program.h"
#include "core/camera.h"
#include "core/image.h"
#include "core/scene.h"
#include "core/tracer.h"

namespace rt::gl {

// One ray's answer (rtbench --gpu): the closest hit's t (0 for a blocked any-hit query,
// infinity for a miss), its triangle within its mesh and its object (~0u: none).
struct GpuRayAnswer {
    float t;
    std::uint32_t prim, object, hit;
};

struct GpuTraceTimes {
    double dispatch_s = 0.0;  // the trace itself (to glFinish)
    double readback_s = 0.0;  // the pixels back into an rt::Image
};

class GpuTracer {
  public:
    // Needs a current context with compute shaders: throws rt::Error("gputrace",
    // "OpenGL", reason) where there are none (compute_unavailable_reason()).
    GpuTracer();

    // The scene's arrays into GPU buffers; returns the seconds it took.
    double upload(const Scene& scene);
    std::size_t uploaded_bytes() const { return bytes_; }

    // Traces `camera`'s pixels into the output buffer (nothing is read back).
    void dispatch(const Camera& camera, const TraceOptions& options);
    // Dispatches and reads the image back (row 0 at the bottom, linear RGB).
    Image render(const Camera& camera, const TraceOptions& options, GpuTraceTimes* times = nullptr);
    // Rays, two rows each: (origin, t_max), (direction, 1 for an any-hit query). The rays
    // go up first (not timed in dispatch_s); returns the answers.
    std::vector<GpuRayAnswer> trace_rays(const std::vector<glm::vec4>& rays, GpuTraceTimes* times);
    // The output buffer of the last dispatch: width x height vec4s, row 0 at the bottom.
    GLuint pixel_buffer() const { return pixels_.get(); }

  private:
    Program& program_for(int max_depth);

    void bind_scene(Program& program);
    void ensure_output(std::size_t count);

    std::map<int, std::unique_ptr<Program>> programs_;  // by stack size
    std::unique_ptr<Program> ray_program_;              // RAY_QUERIES
    BufferHandle queries_;
    BufferHandle nodes_, words_, rows_, objects_, meshes_, materials_, pixels_;
    std::size_t pixel_capacity_ = 0;
    std::map<std::string, unsigned> offsets_;  // where each array starts in words_ and rows_
    unsigned light_count_ = 0, unbounded_count_ = 0;
    bool has_tree_ = false, uploaded_ = false;
    vec3 background_{0.0f}, ambient_{0.0f};
    std::size_t bytes_ = 0;
};

}  // namespace rt::gl
