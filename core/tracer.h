#pragma once
// The Whitted tracer: Phong with shadow feelers at each hit, plus reflected and
// refracted rays, stopped by depth (number) and by accumulated weight (strength).

#include <cstdint>

#include <glm/geometric.hpp>

#include "core/medium.h"
#include "core/ray_tree.h"
#include "core/scene.h"
#include "core/simd.h"

namespace rt {

template <int N>
struct Vec3Lanes;

struct TraceOptions {
    bool shadows = true;
    bool reflections = true;
    bool refractions = true;
    int max_depth = 5;         // bounces after the primary ray
    float min_weight = 0.01f;  // a ray that adds less than this to the pixel is not cast

    bool operator==(const TraceOptions&) const = default;
};

struct RayCounts {
    std::uint64_t primary = 0;
    std::uint64_t shadow = 0;
    std::uint64_t reflected = 0;
    std::uint64_t refracted = 0;

    std::uint64_t total() const { return primary + shadow + reflected + refracted; }
    RayCounts& operator+=(const RayCounts& o) {
        primary += o.primary;
        shadow += o.shadow;
        reflected += o.reflected;
        refracted += o.refracted;
        return *this;
    }
};

// Mirror direction d' = d - 2 (d . n) n, for unit n.
inline vec3 reflect_dir(const vec3& d, const vec3& n) { return d - 2.0f * glm::dot(d, n) * n; }

// Snell's law for a unit direction d meeting a surface whose unit normal n faces it,
// going from index eta_from into eta_to. Nothing on total internal reflection.
struct Refraction {
    bool total_internal_reflection = false;
    vec3 dir{0.0f};
};
Refraction refract_dir(const vec3& d, const vec3& n, float eta_from, float eta_to);

// A camera ray's colour as the sum of its parts: the explain map's raw material
// (core/explain.h). colour() is, bit for bit, what trace_primary returns.
struct PrimaryParts {
    std::uint32_t object = kNoObject;  // the first hit's object index, or kNoObject
    vec3 unblocked{0.0f};              // local Phong with every light unblocked
    vec3 local{0.0f};                  // local Phong as traced, shadow feelers and all
    vec3 reflection{0.0f};             // the reflected ray's colour times the reflectivity
    vec3 refraction{0.0f};             // the refracted ray's times the transparency

    static constexpr std::uint32_t kNoObject = ~0u;
    vec3 colour() const { return local + reflection + refraction; }
};

class Tracer {
  public:
    // With a recorder, every ray traced is also written into its tree (one pixel at a
    // time: trace_primary once per recorder).
    Tracer(const Scene& scene, const TraceOptions& options, RayTreeRecorder* recorder = nullptr)
        : scene_(scene), options_(options), recorder_(recorder) {}

    // The colour seen along a camera ray (linear RGB).
    vec3 trace_primary(const Ray& r, RayCounts& counts) const;
    // The same when the camera ray's first hit is already known (a miss: background).
    vec3 shade_hit(const Ray& r, const Hit& hit, RayCounts& counts) const;
    // A camera ray's colour in parts (a miss: the background, as local and unblocked).
    PrimaryParts trace_parts(const Ray& r, RayCounts& counts) const;
    // The colours of 1 to kPacketWidth camera rays whose first hits are found, rays[k]
    // and hits[k] for each k in `which`: bit for bit what shade_hit gives each one. Their
    // surfaces are built one by one, the local Phong term across SIMD lanes (the lanes'
    // materials, points and normals side by side: twice as fast as one pixel at a time),
    // reflections and refractions ray by ray. Not with a recorder.
    void shade_found(const Ray* rays, const Hit* hits, const std::uint32_t* which, int n,
                     RayCounts& counts, vec3* colours) const;

    // The local Phong term at a surface point: ka Ia + sum over lights of
    // visible(p, l) (kd max(0, n.l) + ks max(0, r.v)^shininess) I_l.
    vec3 phong(const Ray& r, const SurfacePoint& sp, RayCounts& counts) const;

  private:
    // Where a secondary ray stands: its depth, its weight in the pixel, and the media it
    // is inside.
    struct Path {
        int depth = 0;
        float weight = 1.0f;
        MediumStack media;
        RayKind kind = RayKind::kPrimary;        // for the recorder
        bool total_internal_reflection = false;  // likewise
    };
    vec3 trace(const Ray& r, const Path& path, RayCounts& counts) const;
    vec3 trace_recorded(const Ray& r, const Path& path, RayCounts& counts) const;
    vec3 shade(const Ray& r, const Hit& hit, const Path& path, RayCounts& counts) const;
    // shade's terms; with `parts`, also the local term with every light unblocked.
    void shade_parts(const Ray& r, const Hit& hit, const Path& path, RayCounts& counts,
                     PrimaryParts& parts, bool unblocked) const;
    vec3 phong(const Ray& r, const SurfacePoint& sp, RayCounts& counts, bool feelers) const;
    vec3 pattern_at(const Material& m, const SurfacePoint& sp) const;
    // The reflected and refracted rays' terms of shade_parts, from the hit's surface.
    void bounces(const Ray& r, const Hit& hit, const SurfacePoint& sp, const Path& path,
                 RayCounts& counts, PrimaryParts& parts) const;
    // phong for sps[0 .. n), seen along the directions `dirs`, a lane each (dirs[n - 1]
    // followed by a readable float: they are read four floats at a time).
    struct PhongInputs;
    PhongInputs phong_inputs(const SurfacePoint* sps, const vec3* dirs, int n) const;
    void phong_lanes(const SurfacePoint* sps, const vec3* dirs, int n, RayCounts& counts,
                     vec3* local) const;
    // The mirrored ray at sp of r, from sp.p moved off the surface.
    static Ray reflected_ray(const Ray& r, const SurfacePoint& sp) {
        return Ray{offset_ray_origin(sp.p, sp.geometric_normal),
                   reflect_dir(glm::normalize(r.dir), sp.normal)};
    }
    enum class Bounce { kReflection, kInternal, kRefraction };
    static Path next_path(const Path& path, const Material& m, Bounce bounce, std::uint32_t object);
    vec3 reflected(const Ray& r, const SurfacePoint& sp, const Path& path, RayCounts& counts) const;
    void shade_lanes(const Ray* rays, const Hit* hits, const std::uint32_t* which,
                     const Path* paths, int n, RayCounts& counts, vec3* colours) const;
    struct NextRay {
        int k;  // the hit's
        Bounce bounce;
        vec3 refracted;  // kRefraction: the ray's direction
    };
    static const Path& path_of(const Path* paths, const std::uint32_t* which, int k);
    int bounces_of(const Ray* rays, const Hit* hits, const std::uint32_t* which, const Path* paths,
                   const SurfacePoint* sps, int n, RayCounts& counts, NextRay* next) const;
    void bounce_lanes(const Ray* rays, const Hit* hits, const std::uint32_t* which,
                      const Path* paths, const SurfacePoint* sps, int n, RayCounts& counts,
                      vec3* reflection, vec3* refraction) const;
    vec3 refracted(const Ray& r, const Hit& hit, const SurfacePoint& sp, const Path& path,
                   RayCounts& counts) const;
    enum class FeelerCase { kTrace, kSeen, kHidden };
    FeelerCase feeler_to(const vec3& p, const SurfacePoint& sp, const Light& light, Ray& feeler,
                         float& t_max) const;
    bool visible(const vec3& p, const SurfacePoint& sp, const Light& light,
                 RayCounts& counts) const;
    unsigned visible_lanes(const PhongInputs& in, const Vec3Lanes<kPacketWidth>& towards,
                           const SurfacePoint* sps, unsigned lit, const Light& light,
                           RayCounts& counts) const;
    RayHitRecord hit_record(const Ray& r, const Hit& hit) const;
    void record_feeler(const Ray& feeler, float t_max, const Light& light, bool blocked) const;

    const Scene& scene_;
    TraceOptions options_;
    RayTreeRecorder* recorder_ = nullptr;
};

// The ray tree of one pixel of `camera` (x, y from the bottom-left, as Image; inside the
// image), recorded by the tracer as it traces the pixel.
RayNode trace_ray_tree(const Scene& scene, const Camera& camera, const TraceOptions& options, int x,
                       int y);

}  // namespace rt
