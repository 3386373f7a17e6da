#include "core/ray_tree.h"

#include <algorithm>

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
