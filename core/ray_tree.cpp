#include "core/ray_tree.h"

#include <algorithm>

#include <glm/geometric.hpp>

namespace rt {

const char* ray_kind_name(RayKind kind) {
    switch (kind) {
        case RayKind::kPrimary:
            return "primary";
        case RayKind::kShadow:
            return "shadow";
        case RayKind::kReflection:
            return "reflection";
        case RayKind::kRefraction:
            return "refraction";
    }
    return "?";
}

std::vector<RaySegment> ray_segments(const RayNode& root, const std::vector<Light>& lights,
                                     float miss_length) {
    std::vector<RaySegment> out;
    const auto add = [&](const auto& self, const RayNode& n) -> void {
        RaySegment s;
        s.a = n.origin;
        s.kind = n.kind;
        s.blocked = n.blocked;
        const float length = glm::length(n.direction);
        const vec3 unit = length > 0.0f ? n.direction / length : vec3(0.0f);
        if (n.kind == RayKind::kShadow) {
            // A point light's feeler is l - p: it ends at the light (t = 1).
            const bool point =
                n.light >= 0 && static_cast<std::size_t>(n.light) < lights.size() &&
                lights[static_cast<std::size_t>(n.light)].type == Light::Type::kPoint;
            s.b = point ? n.origin + n.direction : n.origin + miss_length * unit;
        } else if (n.hit) {
            s.b = n.hit->point;
        } else {
            s.b = n.origin + miss_length * unit;
            s.miss = true;
        }
        out.push_back(s);
        for (const RayNode& c : n.children) self(self, c);
    };
    add(add, root);
    return out;
}

RayNode& RayTreeRecorder::begin(RayKind kind, const Ray& r, float weight) {
    RayNode node;
    node.kind = kind;
    node.origin = r.origin;
    node.direction = r.dir;
    node.weight = weight;
    RayNode* added = nullptr;
    if (stack_.empty()) {
        root_ = std::move(node);
        started_ = true;
        added = &root_;
    } else {
        stack_.back()->children.push_back(std::move(node));
        added = &stack_.back()->children.back();
    }
    stack_.push_back(added);
    return *added;
}

void RayTreeRecorder::end(const vec3& colour) {
    stack_.back()->colour = colour;
    stack_.pop_back();
}

RayNode& RayTreeRecorder::leaf(RayKind kind, const Ray& r, float weight) {
    RayNode& node = begin(kind, r, weight);
    stack_.pop_back();
    return node;
}

int bounce_depth(const RayNode& node) {
    int depth = 0;
    for (const RayNode& c : node.children)
        if (c.kind != RayKind::kShadow) depth = std::max(depth, 1 + bounce_depth(c));
    return depth;
}

}  // namespace rt
