#include "core/tracer.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include <glm/geometric.hpp>

namespace rt {

Refraction refract_dir(const vec3& d, const vec3& n, float eta_from, float eta_to) {
    const float eta = eta_from / eta_to;
    const float cos_i = -glm::dot(d, n);
    const float sin2_t = eta * eta * std::max(0.0f, 1.0f - cos_i * cos_i);
    if (sin2_t > 1.0f) return {true, vec3(0.0f)};  // past the critical angle
    const float cos_t = std::sqrt(1.0f - sin2_t);
    return {false, eta * d + (eta * cos_i - cos_t) * n};
}

RayNode trace_ray_tree(const Scene& scene, const Camera& camera, const TraceOptions& options, int x,
                       int y) {
    RayTreeRecorder recorder;
    RayCounts counts;
    Tracer(scene, options, &recorder).trace_primary(camera.ray(x, y), counts);
    return recorder.root();
}

vec3 Tracer::trace_primary(const Ray& r, RayCounts& counts) const {
    ++counts.primary;
    return trace(r, Path{}, counts);
}

vec3 Tracer::shade_hit(const Ray& r, const Hit& hit, RayCounts& counts) const {
    return hit.found() ? shade(r, hit, Path{}, counts) : scene_.background;
}

vec3 Tracer::trace(const Ray& r, const Path& path, RayCounts& counts) const {
    if (recorder_) return trace_recorded(r, path, counts);
    Hit hit;
    if (!scene_.intersect(r, hit)) return scene_.background;
    return shade(r, hit, path, counts);
}

// The same, written into the ray tree: the ray, then (in shade) its hit, its shadow
// feelers and its reflected and refracted rays, then the colour it brought back.
vec3 Tracer::trace_recorded(const Ray& r, const Path& path, RayCounts& counts) const {
    RayNode& node = recorder_->begin(path.kind, r, path.weight);
    node.total_internal_reflection = path.total_internal_reflection;
    Hit hit;
    const vec3 colour = scene_.intersect(r, hit) ? shade(r, hit, path, counts) : scene_.background;
    recorder_->end(colour);
    return colour;
}

RayHitRecord Tracer::hit_record(const Ray& r, const Hit& hit) const {
    const SurfacePoint sp = scene_.surface(r, hit);
    return {hit.object, scene_.objects[hit.object].name, hit.t, hit.t * glm::length(r.dir), sp.p,
            sp.normal};
}

vec3 Tracer::shade(const Ray& r, const Hit& hit, const Path& path, RayCounts& counts) const {
    PrimaryParts parts;
    shade_parts(r, hit, path, counts, parts, false);
    return parts.colour();
}

PrimaryParts Tracer::trace_parts(const Ray& r, RayCounts& counts) const {
    ++counts.primary;
    PrimaryParts parts;
    Hit hit;
    if (!scene_.intersect(r, hit)) {
        parts.local = parts.unblocked = scene_.background;
        return parts;
    }
    parts.object = hit.object;
    shade_parts(r, hit, Path{}, counts, parts, true);
    return parts;
}

void Tracer::shade_parts(const Ray& r, const Hit& hit, const Path& path, RayCounts& counts,
                         PrimaryParts& parts, bool unblocked) const {
    const SurfacePoint sp = scene_.surface(r, hit);
    if (recorder_) recorder_->open().hit = hit_record(r, hit);
    parts.local = phong(r, sp, counts, options_.shadows);
    if (unblocked) parts.unblocked = options_.shadows ? phong(r, sp, counts, false) : parts.local;
    if (recorder_) recorder_->open().local = parts.local;
    bounces(r, hit, sp, path, counts, parts);
}

void Tracer::bounces(const Ray& r, const Hit& hit, const SurfacePoint& sp, const Path& path,
                     RayCounts& counts, PrimaryParts& parts) const {
    if (path.depth >= options_.max_depth) return;
    const Material& m = scene_.materials[sp.material];
    // R_n = R_amb + R_diff + R_spec + reflectivity R_(n-1), and the same for transmission.
    if (options_.reflections && m.reflectivity * path.weight >= options_.min_weight) {
        const Path next{path.depth + 1, path.weight * m.reflectivity, path.media,
                        RayKind::kReflection};
        parts.reflection = m.reflectivity * reflected(r, sp, next, counts);
    }
    if (options_.refractions && m.transparency * path.weight >= options_.min_weight) {
        const Path next{path.depth + 1, path.weight * m.transparency, path.media,
                        RayKind::kRefraction};
        parts.refraction = m.transparency * refracted(r, hit, sp, next, counts);
    }
}

vec3 Tracer::phong(const Ray& r, const SurfacePoint& sp, RayCounts& counts) const {
    return phong(r, sp, counts, options_.shadows);
}

// What multiplies ka and kd at a surface point: its checker, texture and vertex colour.
vec3 Tracer::pattern_at(const Material& m, const SurfacePoint& sp) const {
    vec3 pattern = m.checker ? m.checker->at(sp.pattern_point) : vec3(1.0f);
    if (m.texture) pattern *= scene_.textures[*m.texture].sample(sp.uv);
    return pattern * sp.colour;
}

// With `feelers` off every light in front of the surface counts as seen.
vec3 Tracer::phong(const Ray& r, const SurfacePoint& sp, RayCounts& counts, bool feelers) const {
    const Material& m = scene_.materials[sp.material];
    const vec3 pattern = pattern_at(m, sp);
    vec3 colour = m.emission + m.ka * pattern * scene_.ambient;
    const vec3 to_viewer = -glm::normalize(r.dir);
    const vec3 p = offset_ray_origin(sp.p, sp.geometric_normal);
    for (const Light& light : scene_.lights) {
        vec3 to_light;
        light.feeler(sp.p, to_light);
        // A point light exactly on the surface has no direction: it lights nothing there
        // (the limit of n.l as the light comes down onto a plane), rather than NaN.
        const float distance = glm::length(to_light);
        if (!(distance > 0.0f) || !std::isfinite(distance)) continue;
        to_light /= distance;
        const float n_dot_l = glm::dot(sp.normal, to_light);
        if (n_dot_l <= 0.0f) continue;  // the light is behind the surface
        if (feelers && !visible(p, sp, light, counts)) continue;
        const vec3 mirrored = reflect_dir(-to_light, sp.normal);
        const float r_dot_v = std::max(0.0f, glm::dot(mirrored, to_viewer));
        const vec3 specular = r_dot_v > 0.0f ? m.ks * std::pow(r_dot_v, m.shininess) : vec3(0.0f);
        colour += (m.kd * pattern * n_dot_l + specular) * light.colour;
    }
    return colour;
}

// The feeler from p (sp.p moved off the surface) to the light, or, where it points
// behind the moved origin, the answer without one: decided from the true surface point,
// a light behind the surface is not seen; one in front but nearer than the offset (a
// small model, far enough out that float's step there is large) leaves no room for a
// blocker.
[[gnu::always_inline]] inline Tracer::FeelerCase Tracer::feeler_to(const vec3& p,
                                                                   const SurfacePoint& sp,
                                                                   const Light& light, Ray& feeler,
                                                                   float& t_max) const {
    feeler.origin = p;
    t_max = light.feeler(p, feeler.dir);
    if (!(glm::dot(feeler.dir, sp.geometric_normal) <= 0.0f)) return FeelerCase::kTrace;
    vec3 from_surface;
    light.feeler(sp.p, from_surface);
    return glm::dot(from_surface, sp.geometric_normal) > 0.0f ? FeelerCase::kSeen
                                                              : FeelerCase::kHidden;
}

// Inlined into phong, its only caller: the call itself (its arguments, the registers it
// saves) cost as much as the checks around the feeler (callgrind, whitted 640 x 360).
[[gnu::always_inline]] inline bool Tracer::visible(const vec3& p, const SurfacePoint& sp,
                                                   const Light& light, RayCounts& counts) const {
    Ray feeler;
    float t_max = 0.0f;
    const FeelerCase found = feeler_to(p, sp, light, feeler, t_max);
    if (found != FeelerCase::kTrace) return found == FeelerCase::kSeen;
    ++counts.shadow;
    const auto index = static_cast<std::size_t>(&light - scene_.lights.data());
    const bool blocked = scene_.occluded(feeler, t_max, index, sp.cannot_meet_again);
    if (recorder_) record_feeler(feeler, t_max, light, blocked);
    return !blocked;
}

void Tracer::record_feeler(const Ray& feeler, float t_max, const Light& light, bool blocked) const {
    RayNode& node = recorder_->leaf(RayKind::kShadow, feeler, recorder_->open().weight);
    node.light = static_cast<int>(&light - scene_.lights.data());
    node.blocked = blocked;
    Hit first;
    first.t = t_max;
    if (blocked && scene_.intersect(feeler, first)) node.blocker = hit_record(feeler, first);
}

// `path` is the new ray's: one deeper, its weight, and (a reflection stays on its side
// of the surface) the media of the ray that arrived.
vec3 Tracer::reflected(const Ray& r, const SurfacePoint& sp, const Path& path,
                       RayCounts& counts) const {
    ++counts.reflected;
    return trace(reflected_ray(r, sp), path, counts);
}

vec3 Tracer::refracted(const Ray& r, const Hit& hit, const SurfacePoint& sp, const Path& path,
                       RayCounts& counts) const {
    // Entering or leaving follows from the media the ray is inside, not from the winding:
    // the normal already faces the ray, whichever way the surface was wound.
    const MediumStack::Crossing crossing =
        path.media.cross(hit.object, scene_.materials[sp.material].ior);
    const Refraction t =
        refract_dir(glm::normalize(r.dir), sp.normal, crossing.eta_from, crossing.eta_to);
    if (t.total_internal_reflection) {
        // No light crosses: what would have been transmitted is reflected instead.
        Path mirrored = path;
        mirrored.kind = RayKind::kReflection;
        mirrored.total_internal_reflection = true;
        return reflected(r, sp, mirrored, counts);
    }
    ++counts.refracted;
    const Path through{path.depth, path.weight, crossing.after, RayKind::kRefraction};
    return trace(Ray{offset_ray_origin(sp.p, -sp.geometric_normal), t.dir}, through, counts);
}

}  // namespace rt
