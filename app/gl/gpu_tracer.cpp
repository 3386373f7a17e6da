#include "app/gl/gpu_tracer.h"

#include <cstring>

#include "app/gl/context.h"
#include "app/gl/debug.h"
#include "core/error.h"
#include "core/flat_scene.h"
#include "core/stopwatch.h"

namespace rt::gl {
namespace {

template <class T>
void upload_buffer(BufferHandle& buffer, const std::vector<T>& data) {
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffer.get());
    // An empty array still gets a buffer of one element: every binding must have storage.
    const std::size_t bytes = std::max<std::size_t>(sizeof(T), data.size() * sizeof(T));
    glBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(bytes), nullptr, GL_STATIC_DRAW);
    if (!data.empty())
        glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0,
                        static_cast<GLsizeiptr>(data.size() * sizeof(T)), data.data());
}

// Appends `part` to `all` and returns where it starts, in elements of `all`.
template <class T, class U>
unsigned append(std::vector<T>& all, const std::vector<U>& part) {
    static_assert(sizeof(U) % sizeof(T) == 0);
    const auto at = static_cast<unsigned>(all.size());
    const std::size_t n = part.size() * (sizeof(U) / sizeof(T));
    all.resize(all.size() + n);
    if (n != 0) std::memcpy(all.data() + at, part.data(), n * sizeof(T));
    return at;
}

// Rays waiting on the shader's stack: at most one per depth below the ray being traced,
// plus the two a hit pushes. Programs are compiled for a few sizes, not for every depth.
int stack_size(int max_depth) {
    for (int size : {8, 16, 32, 66})
        if (max_depth + 2 <= size) return size;
    return max_depth + 2;
}

}  // namespace

GpuTracer::GpuTracer() {
    const std::string why = compute_unavailable_reason();
    if (!why.empty()) throw Error("gputrace", "OpenGL", why);
    for (BufferHandle* b : {&nodes_, &words_, &rows_, &objects_, &meshes_, &materials_, &pixels_})
        *b = make_buffer();
    program_for(TraceOptions{}.max_depth);  // a broken shader fails here, at once
}

Program& GpuTracer::program_for(int max_depth) {
    const int size = stack_size(max_depth);
    auto& program = programs_[size];
    if (!program)
        program =
            std::make_unique<Program>(shader_dir() / "gputrace.comp",
                                      std::vector<std::string>{"STACK " + std::to_string(size)});
    return *program;
}

double GpuTracer::upload(const Scene& scene) {
    const Stopwatch watch;
    const FlatScene flat = flatten(scene);
    std::vector<std::uint32_t> words;
    offsets_["object_order_at"] = append(words, flat.object_order);
    offsets_["triangle_order_at"] = append(words, flat.triangle_order);
    offsets_["unbounded_at"] = append(words, flat.unbounded);
    offsets_["triangle_materials_at"] = append(words, flat.triangle_materials);
    offsets_["textures_at"] = append(words, flat.textures);
    std::vector<glm::vec4> rows;
    offsets_["vertices_at"] = append(rows, flat.vertices);
    offsets_["normals_at"] = append(rows, flat.corner_normals);
    offsets_["uvs_at"] = append(rows, flat.corner_uvs);
    offsets_["colours_at"] = append(rows, flat.corner_colours);
    offsets_["texels_at"] = append(rows, flat.texels);
    offsets_["lights_at"] = append(rows, flat.lights);
    upload_buffer(nodes_, flat.nodes);
    upload_buffer(words_, words);
    upload_buffer(rows_, rows);
    upload_buffer(objects_, flat.objects);
    upload_buffer(meshes_, flat.meshes);
    upload_buffer(materials_, flat.materials);
    light_count_ = static_cast<unsigned>(flat.lights.size());
    unbounded_count_ = static_cast<unsigned>(flat.unbounded.size());
    has_tree_ = !flat.nodes.empty() && !flat.object_order.empty();
    background_ = scene.background;
    ambient_ = scene.ambient;
    bytes_ = flat.bytes();
    uploaded_ = true;
    glFinish();
    check("GpuTracer::upload");
    return watch.seconds();
}

void GpuTracer::ensure_output(std::size_t count) {
    if (count <= pixel_capacity_) return;
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, pixels_.get());
    glBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(count * sizeof(glm::vec4)),
                 nullptr, GL_DYNAMIC_COPY);
    pixel_capacity_ = count;
}

// The scene's buffers and where its arrays start, for either program.
void GpuTracer::bind_scene(Program& program) {
    if (!uploaded_) throw std::logic_error("GpuTracer: a dispatch before upload");
    program.use();
    for (const auto& [name, at] : offsets_) program.set(name.c_str(), at);
    program.set("light_count", light_count_);
    program.set("unbounded_count", unbounded_count_);
    program.set("has_tree", has_tree_ ? 1 : 0);
    GLuint binding = 0;
    for (const BufferHandle* b :
         {&nodes_, &words_, &rows_, &objects_, &meshes_, &materials_, &pixels_})
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding++, b->get());
}

std::vector<GpuRayAnswer> GpuTracer::trace_rays(const std::vector<glm::vec4>& rays,
                                                GpuTraceTimes* times) {
    const std::size_t count = rays.size() / 2;
    if (!ray_program_)
        ray_program_ = std::make_unique<Program>(
            shader_dir() / "gputrace.comp", std::vector<std::string>{"STACK 8", "RAY_QUERIES 1"});
    if (!queries_) queries_ = make_buffer();
    upload_buffer(queries_, rays);
    ensure_output(count);
    bind_scene(*ray_program_);
    ray_program_->set("query_count", static_cast<unsigned>(count));
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 7, queries_.get());
    glFinish();  // the rays are up: the dispatch alone is timed
    Stopwatch watch;
    const std::size_t groups = std::max<std::size_t>(1, (count + 63) / 64);
    const std::size_t columns = std::min<std::size_t>(groups, 65535);
    glDispatchCompute(static_cast<GLuint>(columns),
                      static_cast<GLuint>((groups + columns - 1) / columns), 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glFinish();
    const double dispatch_s = watch.lap();
    std::vector<GpuRayAnswer> answers(count);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, pixels_.get());
    glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0,
                       static_cast<GLsizeiptr>(count * sizeof(GpuRayAnswer)), answers.data());
    check("GpuTracer::trace_rays");
    if (times) *times = {dispatch_s, watch.seconds()};
    return answers;
}

void GpuTracer::dispatch(const Camera& camera, const TraceOptions& options) {
    ensure_output(static_cast<std::size_t>(camera.cols) * camera.rows);
    Program& program = program_for(options.max_depth);
    bind_scene(program);
    program.set("eye", camera.eye);
    program.set("cam_u", camera.u);
    program.set("cam_v", camera.v);
    program.set("cam_n", camera.n);
    program.set("cam_w", camera.W);
    program.set("cam_h", camera.H);
    program.set("cam_dist", camera.N);
    program.set("size", glm::ivec2(camera.cols, camera.rows));
    program.set("background", background_);
    program.set("ambient", ambient_);
    program.set("shadows", options.shadows ? 1 : 0);
    program.set("reflections", options.reflections ? 1 : 0);
    program.set("refractions", options.refractions ? 1 : 0);
    program.set("max_depth", options.max_depth);
    program.set("min_weight", options.min_weight);
    glDispatchCompute(static_cast<GLuint>((camera.cols + 7) / 8),
                      static_cast<GLuint>((camera.rows + 7) / 8), 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
    check("GpuTracer::dispatch");
}

Image GpuTracer::render(const Camera& camera, const TraceOptions& options, GpuTraceTimes* times) {
    Stopwatch watch;
    dispatch(camera, options);
    glFinish();
    const double dispatch_s = watch.lap();
    Image image(camera.cols, camera.rows);
    std::vector<glm::vec4> rgba(image.pixels.size());
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, pixels_.get());
    glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0,
                       static_cast<GLsizeiptr>(rgba.size() * sizeof(glm::vec4)), rgba.data());
    for (std::size_t i = 0; i < rgba.size(); ++i) image.pixels[i] = vec3(rgba[i]);
    check("GpuTracer::render");
    if (times) *times = {dispatch_s, watch.seconds()};
    return image;
}

}  // namespace rt::gl
