#include "core/flat_scene.h"

#include <variant>

namespace rt {
namespace {

glm::vec4 row(const vec3& v, float w = 0.0f) { return glm::vec4(v, w); }

std::uint32_t size32(std::size_t n) { return static_cast<std::uint32_t>(n); }

// Appends a tree's nodes, its child and leaf indices moved past what is already there.
void append_tree(const Bvh& bvh, std::vector<BvhNode>& nodes, std::vector<std::uint32_t>& order) {
    const std::uint32_t node_base = size32(nodes.size()), order_base = size32(order.size());
    for (BvhNode node : bvh.nodes()) {
        node.first += node.is_leaf() ? order_base : node_base;
        nodes.push_back(node);
    }
    order.insert(order.end(), bvh.order().begin(), bvh.order().end());
}

FlatMesh flatten_mesh(const TriangleMesh& mesh, std::uint32_t max_leaf, FlatScene& out) {
    FlatMesh flat;
    std::vector<Aabb> boxes;
    boxes.reserve(mesh.triangles.size());
    for (const glm::uvec3& t : mesh.triangles) {
        Aabb box;
        for (int k = 0; k < 3; ++k) box.grow(mesh.positions[t[k]]);
        boxes.push_back(box);
    }
    Bvh bvh;
    bvh.build(boxes, max_leaf);
    flat.root = size32(out.nodes.size());
    append_tree(bvh, out.nodes, out.triangle_order);
    flat.triangles = size32(out.vertices.size() / 3);
    for (const glm::uvec3& t : mesh.triangles)
        for (int k = 0; k < 3; ++k) out.vertices.push_back(row(mesh.positions[t[k]]));
    if (!mesh.corner_normals.empty()) {
        flat.normals = size32(out.corner_normals.size() / 3);
        for (const vec3& n : mesh.corner_normals) out.corner_normals.push_back(row(n));
    }
    if (!mesh.corner_uvs.empty()) {
        flat.uvs = size32(out.corner_uvs.size() / 2);
        for (std::size_t i = 0; i + 2 < mesh.corner_uvs.size(); i += 3) {
            const glm::vec2* uv = &mesh.corner_uvs[i];
            out.corner_uvs.emplace_back(uv[0].x, uv[0].y, uv[1].x, uv[1].y);
            out.corner_uvs.emplace_back(uv[2].x, uv[2].y, 0.0f, 0.0f);
        }
    }
    if (!mesh.corner_colours.empty()) {
        flat.colours = size32(out.corner_colours.size() / 3);
        for (const vec3& c : mesh.corner_colours) out.corner_colours.push_back(row(c));
    }
    if (!mesh.materials.empty()) {
        flat.materials = size32(out.triangle_materials.size());
        out.triangle_materials.insert(out.triangle_materials.end(), mesh.materials.begin(),
                                      mesh.materials.end());
    }
    return flat;
}

FlatObject flatten_object(const Scene& scene, std::uint32_t index) {
    const Object& o = scene.objects[index];
    FlatObject flat;
    flat.material = o.material;
    if (o.transform) {
        flat.to_object = o.transform->inv;
        flat.to_world = o.transform->m;
        flat.normal = glm::mat4(o.transform->normal);
        flat.flags |= FlatObject::kTransformed;
    }
    std::visit(Overloaded{[&](const Sphere& s) {
                              flat.kind = FlatObject::kSphere;
                              flat.shape[0] = row(s.centre, s.radius);
                          },
                          [&](const Plane& p) {
                              flat.kind = FlatObject::kPlane;
                              flat.shape[0] = row(p.normal, p.offset);
                          },
                          [&](const Triangle& t) {
                              flat.kind = FlatObject::kTriangle;
                              flat.shape[0] = row(t.a);
                              flat.shape[1] = row(t.b);
                              flat.shape[2] = row(t.c);
                          },
                          [&](const MeshRef& m) {
                              flat.kind = FlatObject::kMesh;
                              flat.mesh = m.mesh;
                              if (m.own_materials) flat.flags |= FlatObject::kOwnMaterials;
                          }},
               o.shape);
    // Where the scene's origin falls in the object's checker frame, split into a float and
    // what float leaves of it, so the shader can fold it into one period (Checker::shift).
    const glm::dvec3 p =
        scene.visit_shape(o, [&](const auto& shape) { return shape.pattern_point(scene.origin); });
    const glm::vec3 hi(p);
    flat.pattern_hi = row(hi);
    flat.pattern_lo = row(glm::vec3(p - glm::dvec3(hi)));
    return flat;
}

FlatMaterial flatten_material(const Material& m) {
    FlatMaterial flat{};
    flat.ka_shininess = row(m.ka, m.shininess);
    flat.kd_reflectivity = row(m.kd, m.reflectivity);
    flat.ks_transparency = row(m.ks, m.transparency);
    flat.emission_ior = row(m.emission, m.ior);
    if (m.checker) {
        flat.checker_a_scale = row(m.checker->colour_a, m.checker->scale);
        flat.checker_b = row(m.checker->colour_b);
    }
    flat.texture[0] = m.texture ? static_cast<std::int32_t>(*m.texture) : -1;
    return flat;
}

}  // namespace

FlatScene flatten(const Scene& scene, std::uint32_t max_leaf) {
    FlatScene out;
    std::vector<Aabb> boxes;
    std::vector<std::uint32_t> bounded;
    for (std::uint32_t i = 0; i < scene.objects.size(); ++i) {
        if (std::holds_alternative<Plane>(scene.objects[i].shape)) {
            out.unbounded.push_back(i);
            continue;
        }
        const Aabb box = scene.object_bounds(scene.objects[i]);
        if (box.empty()) continue;  // an empty mesh
        bounded.push_back(i);
        boxes.push_back(box);
    }
    Bvh top;
    top.build(boxes, 1);
    append_tree(top, out.nodes, out.object_order);
    for (std::uint32_t& slot : out.object_order) slot = bounded[slot];
    for (const TriangleMesh& mesh : scene.meshes)
        out.meshes.push_back(flatten_mesh(mesh, max_leaf, out));
    for (std::uint32_t i = 0; i < scene.objects.size(); ++i)
        out.objects.push_back(flatten_object(scene, i));
    for (const Material& m : scene.materials) {
        out.materials.push_back(flatten_material(m));
        if (m.texture) {
            const Texture& t = scene.textures[*m.texture];
            out.materials.back().texture[1] = static_cast<std::int32_t>(t.wrap_u);
            out.materials.back().texture[2] = static_cast<std::int32_t>(t.wrap_v);
        }
    }
    for (const Texture& t : scene.textures) {
        out.textures.push_back(
            {static_cast<std::int32_t>(out.texels.size()), t.width, t.height, 0});
        for (const vec3& texel : t.texels) out.texels.push_back(row(texel));
    }
    for (const Light& l : scene.lights)
        out.lights.push_back({row(l.position, l.type == Light::Type::kPoint ? 0.0f : 1.0f),
                              row(l.direction), row(l.colour)});
    return out;
}

std::size_t FlatScene::bytes() const {
    const auto size = [](const auto& v) { return v.size() * sizeof(v[0]); };
    return size(nodes) + size(object_order) + size(triangle_order) + size(unbounded) +
           size(objects) + size(meshes) + size(vertices) + size(corner_normals) + size(corner_uvs) +
           size(corner_colours) + size(triangle_materials) + size(materials) + size(textures) +
           size(texels) + size(lights);
}

}  // namespace rt
