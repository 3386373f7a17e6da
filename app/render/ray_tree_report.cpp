#include "app/render/ray_tree_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/tracer.h"

namespace rt::renderer {
namespace {

nlohmann::json vec(const vec3& v) { return {v.x, v.y, v.z}; }

// A point in the scene file's coordinates: the loader moved a far scene's centre to the
// origin (LoadedScene::origin) and read a scene of extreme size in a unit of its own
// (LoadedScene::scale) so that float keeps its precision; both go back here, in double.
// Normals need no such care; a direction is scaled (t, the ray's parameter, is the same
// in either unit).
glm::dvec3 in_file(const vec3& p, const FileFrame& file) {
    return file.origin + file.scale * glm::dvec3(p);
}
nlohmann::json point(const vec3& p, const FileFrame& file) {
    const glm::dvec3 q = in_file(p, file);
    return {q.x, q.y, q.z};
}
vec3 direction(const vec3& d, const FileFrame& file) { return vec3(file.scale * glm::dvec3(d)); }

nlohmann::json hit_json(const std::optional<RayHitRecord>& h, const FileFrame& file) {
    if (!h) return nullptr;
    return {{"object", h->name},
            {"index", h->object},
            {"t", h->t},
            {"distance", file.scale * h->distance},
            {"point", point(h->point, file)},
            {"normal", vec(h->normal)}};
}

nlohmann::json node_json(const RayNode& n, const FileFrame& file) {
    nlohmann::json j = {{"kind", ray_kind_name(n.kind)},
                        {"origin", point(n.origin, file)},
                        {"direction", vec(direction(n.direction, file))},
                        {"weight", n.weight}};
    if (n.kind == RayKind::kShadow) {
        j["light"] = n.light;
        j["blocked"] = n.blocked;
        j["blocker"] = hit_json(n.blocker, file);
    } else {
        j["hit"] = hit_json(n.hit, file);
        j["colour"] = vec(n.colour);
        j["local"] = vec(n.local);
        if (n.total_internal_reflection) j["total_internal_reflection"] = true;
    }
    j["children"] = nlohmann::json::array();
    for (const RayNode& c : n.children) j["children"].push_back(node_json(c, file));
    return j;
}

std::string fmt(const vec3& v) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "(%.4g, %.4g, %.4g)", v.x, v.y, v.z);
    return buf;
}

// A point: as many digits as it takes to tell points 1e-4 apart, far out or not.
std::string fmt_point(const vec3& p, const FileFrame& file) {
    const glm::dvec3 q = in_file(p, file);
    const double largest = std::max({std::abs(q.x), std::abs(q.y), std::abs(q.z), 1.0});
    // Up to float's range (a point not finite, or NaN, prints with float's most digits).
    const int digits = 4 + (largest < 1e39 ? static_cast<int>(std::ceil(std::log10(largest))) : 39);
    char buf[160];
    std::snprintf(buf, sizeof buf, "(%.*g, %.*g, %.*g)", digits, q.x, digits, q.y, digits, q.z);
    return buf;
}

void print_node(const Scene& scene, const RayNode& n, int indent, const FileFrame& file) {
    std::printf("%*s%s", 2 * indent, "", ray_kind_name(n.kind));
    if (n.total_internal_reflection) std::printf(" (total internal reflection)");
    if (n.kind == RayKind::kShadow) {
        const Light& light = scene.lights[static_cast<std::size_t>(n.light)];
        std::printf(" to light %d at %s: ", n.light, fmt_point(light.position, file).c_str());
        if (!n.blocked)
            std::printf("clear\n");
        else if (n.blocker)
            std::printf("blocked by \"%s\" at t=%.4g\n", n.blocker->name.c_str(), n.blocker->t);
        else
            std::printf("blocked\n");
        return;
    }
    std::printf(" from %s dir %s, weight %.4g: ", fmt_point(n.origin, file).c_str(),
                fmt(direction(n.direction, file)).c_str(), n.weight);
    if (n.hit)
        std::printf("hit \"%s\" at t=%.4g, point %s, normal %s; local %s, returns %s\n",
                    n.hit->name.c_str(), n.hit->t, fmt_point(n.hit->point, file).c_str(),
                    fmt(n.hit->normal).c_str(), fmt(n.local).c_str(), fmt(n.colour).c_str());
    else
        std::printf("miss, returns the background %s\n", fmt(n.colour).c_str());
    for (const RayNode& c : n.children) print_node(scene, c, indent + 1, file);
}

}  // namespace

RayNode trace_pixel_tree(const Scene& scene, const Camera& camera, const TraceOptions& options,
                         int x, int y) {
    if (x < 0 || y < 0 || x >= camera.cols || y >= camera.rows)
        throw Error("rtrender", "--ray-tree",
                    "pixel " + std::to_string(x) + "," + std::to_string(y) + " is outside the " +
                        std::to_string(camera.cols) + "x" + std::to_string(camera.rows) + " image");
    return trace_ray_tree(scene, camera, options, x, camera.rows - 1 - y);
}

void print_ray_tree(const Scene& scene, const RayNode& root, int x, int y, const FileFrame& file) {
    std::printf("pixel %d,%d (from the top left): colour %s, %d bounce%s\n", x, y,
                fmt(root.colour).c_str(), bounce_depth(root), bounce_depth(root) == 1 ? "" : "s");
    print_node(scene, root, 1, file);
}

void write_ray_tree_json(const RayNode& root, int x, int y, const std::string& path,
                         const FileFrame& file) {
    const nlohmann::json j = {
        {"pixel", {x, y}}, {"colour", vec(root.colour)}, {"ray", node_json(root, file)}};
    std::ofstream out(path);
    out << j.dump(2) << '\n';
    if (!out) throw Error(path, "--ray-tree-json", "cannot write the file");
}

}  // namespace rt::renderer
