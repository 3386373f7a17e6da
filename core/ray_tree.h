#pragma once
// The rays one pixel spawns, as a tree: what the tracer did, recorded by the tracer
// itself (Tracer takes a RayTreeRecorder; without one it records nothing and costs a
// null check). Each node is one ray: its kind, where it starts and goes, what it hit,
// its weight in the pixel and the colour it brought back; a shadow feeler says which
// light it went to and whether (and by what) it was blocked.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/light.h"
#include "core/ray.h"

namespace rt {

enum class RayKind { kPrimary, kShadow, kReflection, kRefraction };
const char* ray_kind_name(RayKind kind);

struct RayHitRecord {
    std::uint32_t object = 0;
    std::string name;                // the object's
    float t = 0.0f;                  // the ray's parameter: point = origin + t direction (as cast)
    float distance = 0.0f;           // from the origin
    vec3 point{0.0f}, normal{0.0f};  // the normal as shaded: unit, facing the ray
};

struct RayNode {
    RayKind kind = RayKind::kPrimary;
    vec3 origin{0.0f}, direction{0.0f};      // as cast: a camera ray's d, a feeler's l - p
    std::optional<RayHitRecord> hit;         // none: a miss (the background)
    float weight = 1.0f;                     // the ray's share of the pixel
    vec3 colour{0.0f};                       // what it brought back (not for shadow feelers)
    vec3 local{0.0f};                        // of it, the local Phong term at its hit
    bool total_internal_reflection = false;  // a reflection that replaced a refraction
    // Shadow feelers:
    int light = -1;
    bool blocked = false;
    std::optional<RayHitRecord> blocker;  // the nearest object in the way
    std::vector<RayNode> children;        // in the order they were cast
};

// Builds the tree while the tracer runs (one pixel, one thread).
class RayTreeRecorder {
  public:
    RayNode& begin(RayKind kind, const Ray& r, float weight);  // a ray, child of the open one
    void end(const vec3& colour);                              // closes it with its colour
    RayNode& open() { return *stack_.back(); }
    // A closed child of the open ray (a shadow feeler is cast and answered at once).
    RayNode& leaf(RayKind kind, const Ray& r, float weight);

    const RayNode& root() const { return root_; }
    bool empty() const { return !started_; }

  private:
    RayNode root_;
    bool started_ = false;
    std::vector<RayNode*> stack_;  // the open rays: parents never move while a child is open
};

// The tree as line segments, for drawing it in the scene: each ray from its origin to its
// hit; a miss `miss_length` long; a shadow feeler to its light (or, for a directional
// light, `miss_length` towards it), marked blocked or not.
struct RaySegment {
    vec3 a{0.0f}, b{0.0f};
    RayKind kind = RayKind::kPrimary;
    bool blocked = false;  // shadow feelers
    bool miss = false;     // drawn to a fixed length: it hit nothing
};
std::vector<RaySegment> ray_segments(const RayNode& root, const std::vector<Light>& lights,
                                     float miss_length);

// Depth of the tree in bounces: 0 for a primary ray alone; shadow feelers do not count.
int bounce_depth(const RayNode& node);

}  // namespace rt
