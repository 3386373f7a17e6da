#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <numbers>
#include <thread>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "app/bench/bench.h"
#include "core/tessellate.h"

namespace rt::bench {

rt::TriangleMesh flatten(const rt::SceneDescription& scene) {
    rt::TriangleMesh out;
    for (const rt::Object& o : scene.objects) {
        const rt::TriangleMesh mesh = rt::object_triangles(scene.meshes, o, 96);
        const glm::mat4 m = o.transform ? o.transform->m : glm::mat4(1.0f);
        const auto base = static_cast<std::uint32_t>(out.positions.size());
        for (const vec3& p : mesh.positions) out.positions.push_back(vec3(m * glm::vec4(p, 1.0f)));
        for (const glm::uvec3& t : mesh.triangles) out.triangles.push_back(t + glm::uvec3(base));
    }
    return out;
}

namespace {

// A small counter-based generator: the same numbers for the same ray index, always.
float hash01(std::uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return static_cast<float>(x >> 8) / 16777216.0f;
}

vec3 cosine_direction(const vec3& n, std::uint32_t index) {
    const float u1 = hash01(2 * index + 1), u2 = hash01(2 * index + 2);
    const float r = std::sqrt(u1), phi = 2.0f * std::numbers::pi_v<float> * u2;
    vec3 t1, t2;
    rt::tangent_frame(n, t1, t2);
    return r * std::cos(phi) * t1 + r * std::sin(phi) * t2 +
           std::sqrt(std::max(0.0f, 1.0f - u1)) * n;
}

// p (a ray's hit on triangle `prim`, r.at(t)) moved onto the triangle's plane, as a
// renderer finds its hit points (from the barycentrics: Triangle::surface; a plane's
// projected back: Plane::surface), to the precision of floats. r.at(t) itself is off the
// plane by t's rounding times the ray's length: on a ground 120 units wide seen from 100
// away, 2e-5 below it, more than offset_ray_origin's step near zero (1.5e-5), so that
// secondary rays started under the ground and met it from below at t = 1e-5 to 5e-5,
// which our structures' test rejects as within its rounding (core/triangle4.h) and
// Embree's does not: "WRONG" answers on a legal mesh (docs/BENCHMARKS.md).
vec3 on_triangle(const rt::TriangleMesh& mesh, std::uint32_t prim, const vec3& p) {
    const glm::uvec3& tri = mesh.triangles[prim];
    const glm::dvec3 a(mesh.positions[tri[0]]), b(mesh.positions[tri[1]]),
        c(mesh.positions[tri[2]]);
    const glm::dvec3 n = glm::cross(b - a, c - a);
    const double nn = glm::dot(n, n);
    if (!(nn > 0.0)) return p;  // no plane (a hit on it is not possible either)
    const glm::dvec3 q(p);
    return vec3(q - (glm::dot(q - a, n) / nn) * n);
}

}  // namespace

RaySet primary_rays(const rt::Camera& camera) {
    RaySet set{"primary", {}, {}, false};
    for (int y = 0; y < camera.rows; ++y)
        for (int x = 0; x < camera.cols; ++x) {
            set.rays.push_back(camera.ray(x, y));
            set.t_max.push_back(rt::kInfinity);
        }
    return set;
}

std::vector<RaySet> make_ray_sets(const rt::Camera& camera, const rt::TriangleMesh& mesh,
                                  const std::vector<rt::Light>& lights,
                                  const std::vector<Result>& primary_hits) {
    std::vector<RaySet> sets(4);
    sets[0] = primary_rays(camera);
    sets[1].name = "shadow";
    sets[1].occlusion = true;
    sets[2].name = "secondary";
    sets[3].name = "mirror";
    std::vector<vec3> points;  // the hits, offset off their surfaces
    for (std::size_t i = 0; i < primary_hits.size(); ++i) {
        const Result& h = primary_hits[i];
        if (!h.hit()) continue;
        const rt::Ray& r = sets[0].rays[i];
        vec3 n = glm::normalize(mesh.face_normal(h.prim));
        if (glm::dot(n, r.dir) > 0.0f) n = -n;
        points.push_back(rt::offset_ray_origin(on_triangle(mesh, h.prim, r.at(h.t)), n));
        sets[2].rays.push_back({points.back(), cosine_direction(n, static_cast<std::uint32_t>(i))});
        sets[2].t_max.push_back(rt::kInfinity);
        sets[3].rays.push_back({points.back(), glm::reflect(r.dir, n)});
        sets[3].t_max.push_back(rt::kInfinity);
    }
    // Light by light, in the pixels' order: neighbouring feelers go to one light, as a
    // renderer's packets of them would.
    for (const rt::Light& light : lights) {
        for (const vec3& p : points) {
            vec3 dir;
            const float t_max = light.feeler(p, dir);
            sets[1].rays.push_back({p, dir});
            sets[1].t_max.push_back(t_max);
        }
    }
    return sets;
}

void parallel_for(std::size_t count, int threads,
                  const std::function<void(std::size_t, std::size_t)>& body) {
    constexpr std::size_t kChunk = 4096;  // a multiple of kPacketWidth: packets stay whole
    std::atomic<std::size_t> next{0};
    const auto work = [&] {
        for (std::size_t begin; (begin = next.fetch_add(kChunk)) < count;)
            body(begin, std::min(count, begin + kChunk));
    };
    std::vector<std::jthread> pool;
    for (int i = 1; i < threads; ++i) pool.emplace_back(work);
    work();
}

double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

namespace {

class Ours : public Structure {
  public:
    Ours(rt::AccelKind kind, int threads) : kind_(kind), threads_(threads) {}
    std::string name() const override { return rt::accel_name(kind_); }
    void prepare(const rt::TriangleMesh& mesh) override { mesh_ = mesh; }
    void build() override { mesh_.build(kind_, threads_); }
    std::size_t memory_bytes() const override { return mesh_.accel_memory_bytes(); }
    Result intersect(const rt::Ray& ray, float t_max) const override {
        rt::Hit hit;
        hit.t = t_max;
        if (!mesh_.intersect(ray, hit)) return {};
        return {hit.t, hit.prim};
    }
    bool occluded(const rt::Ray& ray, float t_max) const override {
        return mesh_.occluded(ray, t_max);
    }

  protected:
    rt::AccelKind kind_;
    int threads_;
    rt::TriangleMesh mesh_;
};

// The same structure, its rays traced kPacketWidth at a time (core/wide_bvh_packet.h).
class OursPackets : public Ours {
  public:
    using Ours::Ours;
    std::string name() const override { return std::string(rt::accel_name(kind_)) + "-packets"; }
    bool packets() const override { return true; }
    void intersect_packet(const rt::Ray* rays, const float* t_max, int count,
                          Result* out) const override {
        std::array<rt::Hit, rt::kPacketWidth> hits;
        for (int i = 0; i < count; ++i) hits[i].t = t_max[i];
        const unsigned found = mesh_.intersect_packet(rays, hits.data(), (1u << count) - 1u);
        for (int i = 0; i < count; ++i)
            out[i] = (found >> i) & 1u ? Result{hits[i].t, hits[i].prim} : Result{};
    }
    void occluded_packet(const rt::Ray* rays, const float* t_max, int count,
                         Result* out) const override {
        const unsigned blocked = mesh_.occluded_packet(rays, t_max, (1u << count) - 1u);
        for (int i = 0; i < count; ++i) out[i].t = (blocked >> i) & 1u ? 0.0f : rt::kInfinity;
    }
};

}  // namespace

std::unique_ptr<Structure> make_ours(rt::AccelKind kind, int threads, bool packets) {
    if (packets) return std::make_unique<OursPackets>(kind, threads);
    return std::make_unique<Ours>(kind, threads);
}

}  // namespace rt::bench
