#include "app/render/ray_tree_report.h"

#include <cstdio>
#include <fstream>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/tracer.h"

namespace rt::renderer {
namespace {

nlohmann::json vec(const vec3& v) { return {v.x, v.y, v.z}; }

nlohmann::json hit_json(const std::optional<RayHitRecord>& h) {
    if (!h) return nullptr;
    return {{"object", h->name},       {"index", h->object},     {"t", h->t},
            {"distance", h->distance}, {"point", vec(h->point)}, {"normal", vec(h->normal)}};
}

nlohmann::json node_json(const RayNode& n) {
    nlohmann::json j = {{"kind", ray_kind_name(n.kind)},
                        {"origin", vec(n.origin)},
                        {"direction", vec(n.direction)},
                        {"weight", n.weight}};
    if (n.kind == RayKind::kShadow) {
        j["light"] = n.light;
        j["blocked"] = n.blocked;
        j["blocker"] = hit_json(n.blocker);
    } else {
        j["hit"] = hit_json(n.hit);
        j["colour"] = vec(n.colour);
        j["local"] = vec(n.local);
        if (n.total_internal_reflection) j["total_internal_reflection"] = true;
    }
    j["children"] = nlohmann::json::array();
    for (const RayNode& c : n.children) j["children"].push_back(node_json(c));
    return j;
}

std::string fmt(const vec3& v) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "(%.4g, %.4g, %.4g)", v.x, v.y, v.z);
    return buf;
}

void print_node(const Scene& scene, const RayNode& n, int indent) {
    std::printf("%*s%s", 2 * indent, "", ray_kind_name(n.kind));
    if (n.total_internal_reflection) std::printf(" (total internal reflection)");
    if (n.kind == RayKind::kShadow) {
        const Light& light = scene.lights[static_cast<std::size_t>(n.light)];
        std::printf(" to light %d at %s: ", n.light, fmt(light.position).c_str());
        if (!n.blocked)
            std::printf("clear\n");
        else if (n.blocker)
            std::printf("blocked by \"%s\" at t=%.4g\n", n.blocker->name.c_str(), n.blocker->t);
        else
            std::printf("blocked\n");
        return;
    }
    std::printf(" from %s dir %s, weight %.4g: ", fmt(n.origin).c_str(), fmt(n.direction).c_str(),
                n.weight);
    if (n.hit)
        std::printf("hit \"%s\" at t=%.4g, point %s, normal %s; local %s, returns %s\n",
                    n.hit->name.c_str(), n.hit->t, fmt(n.hit->point).c_str(),
                    fmt(n.hit->normal).c_str(), fmt(n.local).c_str(), fmt(n.colour).c_str());
    else
        std::printf("miss, returns the background %s\n", fmt(n.colour).c_str());
    for (const RayNode& c : n.children) print_node(scene, c, indent + 1);
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

void print_ray_tree(const Scene& scene, const RayNode& root, int x, int y) {
    std::printf("pixel %d,%d (from the top left): colour %s, %d bounce%s\n", x, y,
                fmt(root.colour).c_str(), bounce_depth(root), bounce_depth(root) == 1 ? "" : "s");
    print_node(scene, root, 1);
}

void write_ray_tree_json(const RayNode& root, int x, int y, const std::string& path) {
    const nlohmann::json j = {
        {"pixel", {x, y}}, {"colour", vec(root.colour)}, {"ray", node_json(root)}};
    std::ofstream out(path);
    out << j.dump(2) << '\n';
    if (!out) throw Error(path, "--ray-tree-json", "cannot write the file");
}

}  // namespace rt::renderer
