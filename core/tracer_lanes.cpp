// The tracer across SIMD lanes: a run of first hits (and, one depth after another, their
// reflected and refracted rays) shaded kPacketWidth at a time, each lane bit for bit what
// Tracer::shade gives it alone (tests/unit/test_shade_found.cpp).
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>

#include <glm/geometric.hpp>

#include "core/tracer.h"
#include "core/vec3_lanes.h"

namespace rt {

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
    shade_lanes(rays, hits, which, nullptr, n, counts, colours);
}

// shade for rays[which[k]], hits[which[k]] and paths[which[k]] (the camera's, Path{},
// where paths is null), k < n: their surfaces, their local terms across the lanes, then
// their reflected and refracted rays, traced together (bounce_lanes).
void Tracer::shade_lanes(const Ray* rays, const Hit* hits, const std::uint32_t* which,
                         const Path* paths, int n, RayCounts& counts, vec3* colours) const {
    std::array<SurfacePoint, kPacketWidth> sps;
    std::array<vec3, kPacketWidth + 1> dirs{};  // one more: phong_inputs reads a float past each
    std::array<vec3, kPacketWidth> local{};
    const bool on_a_plane = scene_.plane_surfaces(rays, hits, which, n, sps.data());
    for (int k = 0; k < n; ++k) {
        if (!on_a_plane) scene_.surface(rays[which[k]], hits[which[k]], sps[k]);
        dirs[k] = rays[which[k]].dir;
    }
    phong_lanes(sps.data(), dirs.data(), n, counts, local.data());
    std::array<vec3, kPacketWidth> reflection{}, refraction{};
    bounce_lanes(rays, hits, which, paths, sps.data(), n, counts, reflection.data(),
                 refraction.data());
    for (int k = 0; k < n; ++k) colours[k] = local[k] + reflection[k] + refraction[k];  // colour()
}

// The path of a hit's reflected (kReflection), totally internally reflected
// (kInternal) or refracted (kRefraction) ray, as bounces and refracted give it.
Tracer::Path Tracer::next_path(const Path& path, const Material& m, Bounce bounce,
                               std::uint32_t object) {
    switch (bounce) {
        case Bounce::kReflection:
            return Path{path.depth + 1, path.weight * m.reflectivity, path.media,
                        RayKind::kReflection};
        case Bounce::kInternal:
            return Path{path.depth + 1, path.weight * m.transparency, path.media,
                        RayKind::kReflection, true};
        case Bounce::kRefraction:
            break;
    }
    return Path{path.depth + 1, path.weight * m.transparency, path.media.cross(object, m.ior).after,
                RayKind::kRefraction};
}

namespace {
// Fewer rays than this, of a run's bounces, are traced one by one (trace), without a
// packet's set-up. 1, 2, 3 and 4 gave whitted's frames alike within the probe's noise.
constexpr int kBouncesTogether = 3;
}  // namespace

// The camera's path where `paths` is null.
const Tracer::Path& Tracer::path_of(const Path* paths, const std::uint32_t* which, int k) {
    static const Path kCamera{};
    return paths ? paths[which[k]] : kCamera;
}

// The reflected and refracted rays of a run's hits, as bounces and refracted cast them
// (and count them), written to `next`, up to two a hit; returns how many.
int Tracer::bounces_of(const Ray* rays, const Hit* hits, const std::uint32_t* which,
                       const Path* paths, const SurfacePoint* sps, int n, RayCounts& counts,
                       NextRay* next) const {
    int m = 0;
    for (int k = 0; k < n; ++k) {
        const Path& path = path_of(paths, which, k);
        const SurfacePoint& sp = sps[k];
        if (path.depth >= options_.max_depth) continue;
        const Material& mat = scene_.materials[sp.material];
        if (options_.reflections && mat.reflectivity * path.weight >= options_.min_weight) {
            ++counts.reflected;
            next[m].k = k;
            next[m++].bounce = Bounce::kReflection;
        }
        if (options_.refractions && mat.transparency * path.weight >= options_.min_weight) {
            const MediumStack::Crossing crossing = path.media.cross(hits[which[k]].object, mat.ior);
            const Refraction t = refract_dir(glm::normalize(rays[which[k]].dir), sp.normal,
                                             crossing.eta_from, crossing.eta_to);
            next[m].k = k;
            if (t.total_internal_reflection) {
                ++counts.reflected;
                next[m++].bounce = Bounce::kInternal;
            } else {
                ++counts.refracted;
                next[m].refracted = t.dir;
                next[m++].bounce = Bounce::kRefraction;
            }
        }
    }
    return m;
}

// A run's reflected and refracted rays (bounces' and refracted's: the same rays, paths
// and counts), up to two a hit, traced kPacketWidth at a time through the scene's
// packets, and those that hit shaded together again (shade_lanes), one depth deeper.
// Their colours, times the reflectivity or transparency, go to `reflection` and
// `refraction` (a total internal reflection's to `refraction`, as in bounces).
// bounces and refracted stay the one-ray reference that the ShadeFound tests hold these
// to, bit for bit, rather than calls of the same code.
void Tracer::bounce_lanes(const Ray* rays, const Hit* hits, const std::uint32_t* which,
                          const Path* paths, const SurfacePoint* sps, int n, RayCounts& counts,
                          vec3* reflection, vec3* refraction) const {
    std::array<NextRay, 2 * kPacketWidth> next;  // not initialised: most runs have no bounces
    const int m = bounces_of(rays, hits, which, paths, sps, n, counts, next.data());
    if (m == 0) return;
    const auto ray_at = [&](int j) {
        const SurfacePoint& sp = sps[next[j].k];
        return next[j].bounce == Bounce::kRefraction
                   ? Ray{offset_ray_origin(sp.p, -sp.geometric_normal), next[j].refracted}
                   : reflected_ray(rays[which[next[j].k]], sp);
    };
    const auto taken = [&](int j, const vec3& colour) {
        const int k = next[j].k;
        const Material& mat = scene_.materials[sps[k].material];
        if (next[j].bounce == Bounce::kReflection)
            reflection[k] = mat.reflectivity * colour;
        else
            refraction[k] = mat.transparency * colour;
    };
    const auto path_at = [&](int j) {
        const int k = next[j].k;
        return next_path(path_of(paths, which, k), scene_.materials[sps[k].material],
                         next[j].bounce, hits[which[k]].object);
    };
    for (int first = 0; first < m; first += kPacketWidth) {
        const int count = std::min(kPacketWidth, m - first);
        if (count < kBouncesTogether) {
            for (int j = first; j < first + count; ++j)
                taken(j, trace(ray_at(j), path_at(j), counts));
            continue;
        }
        std::array<Ray, kPacketWidth> next_rays;
        for (int j = 0; j < count; ++j) next_rays[j] = ray_at(first + j);
        std::array<Hit, kPacketWidth> found_hits{};
        const unsigned found =
            scene_.intersect_packet(next_rays.data(), found_hits.data(), (1u << count) - 1u);
        std::array<Path, kPacketWidth> found_paths;
        std::array<std::uint32_t, kPacketWidth> hit_lanes;
        int h = 0;
        for (unsigned rest = found; rest != 0; rest &= rest - 1) {
            const int j = __builtin_ctz(rest);
            found_paths[j] = path_at(first + j);
            hit_lanes[h++] = static_cast<std::uint32_t>(j);
        }
        std::array<vec3, kPacketWidth> colours;
        if (h > 0)
            shade_lanes(next_rays.data(), found_hits.data(), hit_lanes.data(), found_paths.data(),
                        h, counts, colours.data());
        for (int j = 0, c = 0; j < count; ++j)
            taken(first + j, ((found >> j) & 1u) != 0 ? colours[c++] : scene_.background);
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

}  // namespace rt
