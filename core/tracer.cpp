#include "core/tracer.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>

#include <glm/geometric.hpp>

#include "core/vec3_lanes.h"

namespace rt {
vec3 reflect_dir(const vec3& d, const vec3& n) { return d - 2.0f * glm::dot(d, n) * n; }

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

namespace {
using ShadeLanes = Vec3Lanes<kPacketWidth>;

// Checker::at across the lanes, the same operations on each.
ShadeLanes checker_lanes(const Checker& c, const ShadeLanes& p) {
    using Float = ShadeLanes::Float;
    const Float scale = splat<Float>(c.scale);
    const auto parity = [&](Float x) {
        const Float f = vfloor(x / scale);
        return f - splat<Float>(2.0f) * vfloor(splat<Float>(0.5f) * f);
    };
    const Float sum = parity(p.x) + parity(p.y) + parity(p.z);
    return select((sum == splat<Float>(0.0f)) | (sum == splat<Float>(2.0f)),
                  ShadeLanes::splat(c.colour_a), ShadeLanes::splat(c.colour_b));
}
}  // namespace

// The local terms of several pixels at once: what phong reads, a pixel to a lane.
struct Tracer::PhongInputs {
    ShadeLanes pattern, ka, kd, ks, emission, p, normal, to_viewer;
    ShadeLanes::Float shininess;
    ShadeLanes geometric, origin;  // with feelers: the geometric normal, the feelers' origin
};

void Tracer::shade_found(const Ray* rays, const Hit* hits, const std::uint32_t* which, int n,
                         RayCounts& counts, vec3* colours) const {
    std::array<SurfacePoint, kPacketWidth> sps;
    std::array<vec3, kPacketWidth + 1> dirs{};  // one more: phong_inputs reads a float past each
    std::array<vec3, kPacketWidth> local{};
    const bool on_a_plane = scene_.plane_surfaces(rays, hits, which, n, sps.data());
    for (int k = 0; k < n; ++k) {
        if (!on_a_plane) scene_.surface(rays[which[k]], hits[which[k]], sps[k]);
        dirs[k] = rays[which[k]].dir;
    }
    phong_lanes(sps.data(), dirs.data(), n, counts, local.data());
    for (int k = 0; k < n; ++k) {
        PrimaryParts parts;
        parts.local = local[k];
        bounces(rays[which[k]], hits[which[k]], sps[k], Path{}, counts, parts);
        colours[k] = parts.colour();
    }
}

// Lanes past n repeat lane 0. Neighbouring pixels mostly show one material: then its
// terms are splat, not gathered lane by lane, and a checker (without a texture) is
// evaluated across the lanes.
Tracer::PhongInputs Tracer::phong_inputs(const SurfacePoint* sps, const vec3* dirs, int n) const {
    PhongInputs in;
    bool one_material = true;
    for (int k = 1; k < n; ++k) one_material &= sps[k].material == sps[0].material;
    if (one_material) {
        const Material& m = scene_.materials[sps[0].material];
        in.ka = ShadeLanes::splat(m.ka);
        in.kd = ShadeLanes::splat(m.kd);
        in.ks = ShadeLanes::splat(m.ks);
        in.emission = ShadeLanes::splat(m.emission);
        in.shininess = splat<ShadeLanes::Float>(m.shininess);
    }
    const Material& first = scene_.materials[sps[0].material];
    const bool checker_across = one_material && first.checker && !first.texture;
    // Each of a SurfacePoint's vectors is followed by another field: a row of four floats.
    static_assert(offsetof(SurfacePoint, colour) + 4 * sizeof(float) <= sizeof(SurfacePoint));
    const auto rows_of = [&](const vec3* v) {  // v[0 .. n) with a float after the last
        std::array<const float*, kPacketWidth> rows;
        for (int lane = 0; lane < kPacketWidth; ++lane) rows[lane] = &v[lane < n ? lane : 0].x;
        return ShadeLanes::transpose(rows, 0);
    };
    const auto field = [&](vec3 SurfacePoint::*member) {
        std::array<const float*, kPacketWidth> rows;
        for (int lane = 0; lane < kPacketWidth; ++lane)
            rows[lane] = &(sps[lane < n ? lane : 0].*member).x;
        return ShadeLanes::transpose(rows, 0);
    };
    if (checker_across) {
        in.pattern = checker_lanes(*first.checker, field(&SurfacePoint::pattern_point)) *
                     field(&SurfacePoint::colour);
    }
    std::array<vec3, kPacketWidth + 1> patterns;  // one more: a row of four floats each
    if (!checker_across || !one_material) {
        for (int lane = 0; lane < kPacketWidth; ++lane) {
            const int k = lane < n ? lane : 0;
            const Material& m = scene_.materials[sps[k].material];
            if (!checker_across) patterns[lane] = pattern_at(m, sps[k]);
            if (!one_material) {
                in.ka.set(lane, m.ka);
                in.kd.set(lane, m.kd);
                in.ks.set(lane, m.ks);
                in.emission.set(lane, m.emission);
                in.shininess[lane] = m.shininess;
            }
        }
    }
    if (!checker_across) in.pattern = rows_of(patterns.data());
    in.p = field(&SurfacePoint::p);
    in.normal = field(&SurfacePoint::normal);
    if (options_.shadows) in.geometric = field(&SurfacePoint::geometric_normal);
    in.to_viewer = -normalize(rows_of(dirs));  // dirs has a float after its last
    if (options_.shadows) in.origin = offset_ray_origin(in.p, in.geometric);
    return in;
}

namespace {
// Light::feeler's direction from the points `from`, lane by lane.
ShadeLanes feeler_lanes(const Light& light, const ShadeLanes& from) {
    return light.type == Light::Type::kPoint ? ShadeLanes::splat(light.position) - from
                                             : ShadeLanes::splat(-light.direction);
}
}  // namespace

// visible for the lanes of `lit` at once (feeler_to's cases, then the scene's test of
// the feelers together). `towards`: the light's direction from each surface point.
// Returns the bits of those that see the light.
unsigned Tracer::visible_lanes(const PhongInputs& in, const ShadeLanes& towards,
                               const SurfacePoint* sps, unsigned lit, const Light& light,
                               RayCounts& counts) const {
    using Float = ShadeLanes::Float;
    const ShadeLanes dir = feeler_lanes(light, in.origin);
    const unsigned traced = lit & ~bits(dot(dir, in.geometric) <= splat<Float>(0.0f));
    const unsigned seen = lit & ~traced & bits(dot(towards, in.geometric) > splat<Float>(0.0f));
    if (traced == 0) return seen;
    std::array<std::uint32_t, kPacketWidth> leaving;
    const float t_max = light.type == Light::Type::kPoint ? 1.0f : kInfinity;  // Light::feeler
    std::array<float, kPacketWidth> limits;
    limits.fill(t_max);
    for (unsigned rest = traced; rest != 0; rest &= rest - 1) {
        const int k = __builtin_ctz(rest);
        leaving[k] = sps[k].cannot_meet_again;
    }
    counts.shadow += static_cast<std::uint64_t>(std::popcount(traced));
    const auto index = static_cast<std::size_t>(&light - scene_.lights.data());
    const RayLanes<kPacketWidth> feelers{{in.origin.x, in.origin.y, in.origin.z},
                                         {dir.x, dir.y, dir.z}};
    const unsigned blocked =
        scene_.occluded_packet(feelers, limits.data(), index, leaving.data(), traced);
    if (recorder_)
        for (unsigned rest = traced; rest != 0; rest &= rest - 1) {
            const int k = __builtin_ctz(rest);
            record_feeler(feelers.lane(k), t_max, light, ((blocked >> k) & 1u) != 0);
        }
    return seen | (traced & ~blocked);
}

// phong, a pixel to a lane: the same operations in the same order, so each lane's
// colour is phong's bit for bit. Feelers and powers are taken lane by lane.
void Tracer::phong_lanes(const SurfacePoint* sps, const vec3* dirs, int n, RayCounts& counts,
                         vec3* local) const {
    using Float = ShadeLanes::Float;
    const PhongInputs in = phong_inputs(sps, dirs, n);
    const Float zero = splat<Float>(0.0f);
    ShadeLanes colour = in.emission + in.ka * in.pattern * ShadeLanes::splat(scene_.ambient);
    const unsigned used = (1u << n) - 1u;
    for (const Light& light : scene_.lights) {
        const ShadeLanes towards = feeler_lanes(light, in.p);  // light.feeler(sp.p)
        const Float distance = vsqrt(dot(towards, towards));
        const ShadeLanes to_light = towards / distance;
        const Float n_dot_l = dot(in.normal, to_light);
        unsigned lit =
            bits((distance > zero) & (distance < splat<Float>(kInfinity)) & (n_dot_l > zero)) &
            used;
        if (options_.shadows && lit != 0) lit = visible_lanes(in, towards, sps, lit, light, counts);
        if (lit == 0) continue;
        const ShadeLanes from_light = -to_light;  // reflect_dir(-to_light, normal)
        const ShadeLanes mirrored =
            from_light - in.normal * (splat<Float>(2.0f) * dot(from_light, in.normal));
        const Float r_dot_v = vmax(dot(mirrored, in.to_viewer), zero);
        Float power = zero;
        const unsigned shiny = lit & bits(r_dot_v > zero);
        for (unsigned rest = shiny; rest != 0; rest &= rest - 1) {
            const int k = __builtin_ctz(rest);
            power[k] = std::pow(r_dot_v[k], in.shininess[k]);
        }
        const ShadeLanes specular =
            select(ShadeLanes::mask(shiny), in.ks * power, ShadeLanes::splat(vec3(0.0f)));
        const ShadeLanes term =
            (in.kd * in.pattern * n_dot_l + specular) * ShadeLanes::splat(light.colour);
        colour = select(ShadeLanes::mask(lit), colour + term, colour);
    }
    for (int k = 0; k < n; ++k) local[k] = colour.get(k);
}

// `path` is the new ray's: one deeper, its weight, and (a reflection stays on its side
// of the surface) the media of the ray that arrived.
vec3 Tracer::reflected(const Ray& r, const SurfacePoint& sp, const Path& path,
                       RayCounts& counts) const {
    ++counts.reflected;
    const vec3 d = reflect_dir(glm::normalize(r.dir), sp.normal);
    return trace(Ray{offset_ray_origin(sp.p, sp.geometric_normal), d}, path, counts);
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
