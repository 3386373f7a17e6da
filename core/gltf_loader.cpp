#include "core/gltf_loader.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <set>

#include <tiny_gltf.h>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>

#include "core/error.h"
#include "core/file_kind.h"
#include "core/gltf_material.h"

namespace rt {
namespace {

// Extensions whose meaning the loader takes in; any other is named in one warning.
const std::set<std::string> kUnderstood = {"KHR_materials_transmission", "KHR_materials_ior",
                                           "KHR_lights_punctual"};

std::string at(const char* array, int index) {
    return "/" + std::string(array) + "/" + std::to_string(index);
}

// Images are decoded through OpenImageIO (core/texture.h), not by tinygltf: it hands
// over the encoded bytes (of a file, a data URI or a .glb's buffer), kept as they are.
bool keep_encoded(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                  const unsigned char* bytes, int size, void*) {
    image->image.assign(bytes, bytes + size);
    image->width = image->height = -1;  // not decoded
    return true;
}

Wrap wrap_mode(int gl) {
    return gl == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE     ? Wrap::kClamp
           : gl == TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT ? Wrap::kMirror
                                                         : Wrap::kRepeat;
}

// One component of an accessor's element, as a double (normalised integers to [0, 1] or
// [-1, 1], as the specification says).
double component(const unsigned char* p, int type, bool normalized) {
    const auto read = [&](auto value, double scale) {
        std::memcpy(&value, p, sizeof value);
        const double v = static_cast<double>(value);
        return normalized ? std::max(v / scale, -1.0) : v;
    };
    switch (type) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
            return read(std::int8_t{}, 127.0);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return read(std::uint8_t{}, 255.0);
        case TINYGLTF_COMPONENT_TYPE_SHORT:
            return read(std::int16_t{}, 32767.0);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            return read(std::uint16_t{}, 65535.0);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
            return read(std::uint32_t{}, 4294967295.0);
        default:
            return read(float{}, 1.0);
    }
}

class GltfReader {
  public:
    GltfReader(std::filesystem::path path, const MeshFileOptions& options)
        : path_(std::move(path)), file_(path_.string()), options_(options) {}

    GltfScene read();

  private:
    [[noreturn]] void fail(const std::string& where, const std::string& what) const {
        throw Error(file_, where, what);
    }
    void warn(const std::string& where, const std::string& what) {
        scene_.geometry.warnings.push_back(file_ + ": " + where + ": " + what);
    }
    void parse();
    void check_extensions();
    std::vector<int> root_nodes();
    void walk(int node, const glm::dmat4& parent, std::vector<int>& path);
    glm::dmat4 local_matrix(const tinygltf::Node& n, const std::string& where) const;
    void add_mesh(int mesh, const glm::dmat4& world, const std::string& where);
    void add_primitive(const tinygltf::Primitive& p, const glm::dmat4& world,
                       const std::string& where);
    void add_camera(int camera, const glm::dmat4& world, const std::string& where);
    void add_light(const tinygltf::Value& ext, const glm::dmat4& world, const std::string& where);
    Material material(int index);
    std::uint32_t texture(int index, const std::string& where);
    // An accessor's elements of `width` components each, checked against its buffer.
    std::vector<double> elements(int accessor, int width, const std::string& where) const;
    // A primitive's per-vertex attribute `name` (empty if absent), one element a vertex.
    // Width 0: 3 or 4 components, as the accessor has (told through `width_out`).
    std::vector<double> attribute(const tinygltf::Primitive& p, const std::string& name, int width,
                                  std::size_t vertices, const std::string& where,
                                  int* width_out = nullptr) const;
    void finish();

    std::filesystem::path path_;
    std::string file_;
    MeshFileOptions options_;
    tinygltf::Model model_;
    GltfScene scene_;
    std::vector<glm::dvec3> positions_;  // in the file's coordinates, before the origin
    std::vector<glm::dvec3> normals_;    // per corner, or empty per triangle (flat)
    std::vector<bool> has_normals_;      // per triangle
    std::vector<glm::vec2> uvs_;         // per corner, (0, 0) where a primitive has none
    bool any_uvs_ = false;
    std::vector<vec3> colours_;  // per corner, white where a primitive has none
    bool any_colours_ = false;
    std::map<int, std::uint32_t> texture_of_;  // glTF texture -> MeshFile::textures
    std::vector<glm::dvec3> camera_eyes_;
    struct PendingLight {
        Light light;
        glm::dvec3 position;
        double intensity;
    };
    std::vector<PendingLight> lights_;
    int skipped_primitives_ = 0;
};

void GltfReader::parse() {
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(keep_encoded, nullptr);
    std::string err, warn;
    const bool binary = lower_extension(path_) == ".glb";
    const bool ok = binary ? loader.LoadBinaryFromFile(&model_, &err, &warn, file_)
                           : loader.LoadASCIIFromFile(&model_, &err, &warn, file_);
    if (!ok) {
        std::string what = err.empty() ? "not a glTF 2.0 file" : err;
        while (!what.empty() && (what.back() == '\n' || what.back() == ' ')) what.pop_back();
        std::replace(what.begin(), what.end(), '\n', ';');
        fail("load", what);
    }
}

void GltfReader::check_extensions() {
    for (const std::string& e : model_.extensionsRequired)
        if (!kUnderstood.count(e))
            fail("/extensionsRequired",
                 "requires the extension " + e + ", which rtview cannot read");
    std::string unknown;
    for (const std::string& e : model_.extensionsUsed)
        if (!kUnderstood.count(e)) unknown += (unknown.empty() ? "" : ", ") + e;
    if (!unknown.empty()) warn("/extensionsUsed", "ignored: " + unknown);
}

std::vector<int> GltfReader::root_nodes() {
    const int count = static_cast<int>(model_.scenes.size());
    if (count > 0) {
        const int s =
            model_.defaultScene >= 0 && model_.defaultScene < count ? model_.defaultScene : 0;
        return model_.scenes[static_cast<std::size_t>(s)].nodes;
    }
    std::vector<bool> child(model_.nodes.size(), false);  // no scene: every root node
    for (const tinygltf::Node& n : model_.nodes)
        for (int c : n.children)
            if (c >= 0 && c < static_cast<int>(child.size()))
                child[static_cast<std::size_t>(c)] = true;
    std::vector<int> roots;
    for (std::size_t i = 0; i < child.size(); ++i)
        if (!child[i]) roots.push_back(static_cast<int>(i));
    return roots;
}

glm::dmat4 GltfReader::local_matrix(const tinygltf::Node& n, const std::string& where) const {
    if (n.matrix.size() == 16) return glm::make_mat4(n.matrix.data());  // column-major, as glTF
    glm::dmat4 m(1.0);
    if (n.translation.size() == 3) m = glm::translate(m, glm::make_vec3(n.translation.data()));
    if (n.rotation.size() == 4) {
        const glm::dquat q(n.rotation[3], n.rotation[0], n.rotation[1], n.rotation[2]);
        if (!(glm::length(q) > 0.0)) fail(where + "/rotation", "the quaternion is zero");
        m *= glm::mat4_cast(glm::normalize(q));
    }
    if (n.scale.size() == 3) m = glm::scale(m, glm::make_vec3(n.scale.data()));
    return m;
}

void GltfReader::walk(int node, const glm::dmat4& parent, std::vector<int>& path) {
    const std::string where = at("nodes", node);
    if (node < 0 || node >= static_cast<int>(model_.nodes.size()))
        fail(where, "no such node (the file has " + std::to_string(model_.nodes.size()) + ")");
    if (std::find(path.begin(), path.end(), node) != path.end())
        fail(where, "the node is its own ancestor (the hierarchy must be a tree)");
    const tinygltf::Node& n = model_.nodes[static_cast<std::size_t>(node)];
    const glm::dmat4 world = parent * local_matrix(n, where);
    if (n.mesh >= 0) add_mesh(n.mesh, world, where);
    if (n.camera >= 0) add_camera(n.camera, world, where);
    if (const auto it = n.extensions.find("KHR_lights_punctual"); it != n.extensions.end())
        add_light(it->second, world, where);
    path.push_back(node);
    for (int c : n.children) walk(c, world, path);
    path.pop_back();
}

std::vector<double> GltfReader::elements(int index, int width, const std::string& where) const {
    if (index < 0 || index >= static_cast<int>(model_.accessors.size()))
        fail(where, "no such accessor " + std::to_string(index));
    const tinygltf::Accessor& a = model_.accessors[static_cast<std::size_t>(index)];
    const std::string here = at("accessors", index);
    if (a.sparse.isSparse) fail(here, "sparse accessors are not supported");
    if (tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(a.type)) != width)
        fail(here, "expected " + std::to_string(width) + " components an element");
    std::vector<double> out(a.count * static_cast<std::size_t>(width), 0.0);
    if (a.bufferView < 0) return out;  // all zeros, as the specification says
    if (a.bufferView >= static_cast<int>(model_.bufferViews.size()))
        fail(here, "no such bufferView " + std::to_string(a.bufferView));
    const tinygltf::BufferView& v = model_.bufferViews[static_cast<std::size_t>(a.bufferView)];
    if (v.buffer < 0 || v.buffer >= static_cast<int>(model_.buffers.size()))
        fail(at("bufferViews", a.bufferView), "no such buffer " + std::to_string(v.buffer));
    const std::vector<unsigned char>& data =
        model_.buffers[static_cast<std::size_t>(v.buffer)].data;
    const int size = tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(a.componentType));
    if (size <= 0) fail(here, "unknown component type " + std::to_string(a.componentType));
    const std::size_t element = static_cast<std::size_t>(size) * static_cast<std::size_t>(width);
    const std::size_t stride = v.byteStride > 0 ? v.byteStride : element;
    const std::size_t first = v.byteOffset + a.byteOffset;
    const std::size_t end = a.count == 0 ? first : first + (a.count - 1) * stride + element;
    if (v.byteOffset + v.byteLength > data.size() || a.byteOffset + (end - first) > v.byteLength ||
        end < first)
        fail(here, "its " + std::to_string(a.count) + " elements run past the end of its buffer");
    for (std::size_t i = 0; i < a.count; ++i)
        for (int c = 0; c < width; ++c)
            out[i * static_cast<std::size_t>(width) + static_cast<std::size_t>(c)] =
                component(data.data() + first + i * stride + static_cast<std::size_t>(c * size),
                          a.componentType, a.normalized);
    return out;
}

std::vector<double> GltfReader::attribute(const tinygltf::Primitive& p, const std::string& name,
                                          int width, std::size_t vertices, const std::string& where,
                                          int* width_out) const {
    const auto it = p.attributes.find(name);
    if (it == p.attributes.end()) return {};
    if (width == 0 && it->second >= 0 && it->second < static_cast<int>(model_.accessors.size()))
        width = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(
            model_.accessors[static_cast<std::size_t>(it->second)].type));
    if (width_out) {
        if (width != 3 && width != 4)
            fail(at("accessors", it->second), name + " must be VEC3 or VEC4");
        *width_out = width;
    }
    std::vector<double> values = elements(it->second, width, where + "/attributes/" + name);
    if (values.size() != vertices * static_cast<std::size_t>(width))
        fail(at("accessors", it->second), "not one " + name + " a vertex");
    return values;
}

void GltfReader::add_mesh(int mesh, const glm::dmat4& world, const std::string& where) {
    if (mesh >= static_cast<int>(model_.meshes.size()))
        fail(where + "/mesh", "no such mesh " + std::to_string(mesh));
    const tinygltf::Mesh& m = model_.meshes[static_cast<std::size_t>(mesh)];
    for (std::size_t i = 0; i < m.primitives.size(); ++i)
        add_primitive(m.primitives[i], world,
                      at("meshes", mesh) + "/primitives/" + std::to_string(i));
}

// Corner indices of the primitive's triangles (lists, strips and fans).
std::vector<std::uint32_t> triangle_corners(const std::vector<std::uint32_t>& index, int mode) {
    std::vector<std::uint32_t> out;
    const std::size_t n = index.size();
    if (mode == TINYGLTF_MODE_TRIANGLES) {
        out.assign(index.begin(), index.begin() + static_cast<std::ptrdiff_t>(n - n % 3));
    } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
        for (std::size_t i = 2; i < n; ++i) {  // every other one turned, to keep the winding
            const bool odd = i % 2 == 1;
            out.insert(out.end(), {index[i - 2], index[odd ? i : i - 1], index[odd ? i - 1 : i]});
        }
    } else {  // fan
        for (std::size_t i = 2; i < n; ++i)
            out.insert(out.end(), {index[0], index[i - 1], index[i]});
    }
    return out;
}

void GltfReader::add_primitive(const tinygltf::Primitive& p, const glm::dmat4& world,
                               const std::string& where) {
    if (p.mode != TINYGLTF_MODE_TRIANGLES && p.mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
        p.mode != TINYGLTF_MODE_TRIANGLE_FAN) {
        ++skipped_primitives_;  // points and lines: the tracer renders surfaces
        return;
    }
    const auto pos = p.attributes.find("POSITION");
    if (pos == p.attributes.end()) fail(where + "/attributes", "no POSITION");
    const std::vector<double> xyz = elements(pos->second, 3, where + "/attributes/POSITION");
    const std::size_t vertices = xyz.size() / 3;
    std::vector<std::uint32_t> index(vertices);
    if (p.indices >= 0) {
        const std::vector<double> raw = elements(p.indices, 1, where + "/indices");
        index.resize(raw.size());
        for (std::size_t i = 0; i < raw.size(); ++i) {
            if (!(raw[i] >= 0.0 && raw[i] < static_cast<double>(vertices)))
                fail(at("accessors", p.indices),
                     "index " + std::to_string(static_cast<long long>(std::min(raw[i], 1e18))) +
                         " is past the last vertex (" + std::to_string(vertices) + ")");
            index[i] = static_cast<std::uint32_t>(raw[i]);
        }
    } else {
        for (std::size_t i = 0; i < vertices; ++i) index[i] = static_cast<std::uint32_t>(i);
    }
    const std::vector<double> normals = attribute(p, "NORMAL", 3, vertices, where);
    const std::vector<double> uv = attribute(p, "TEXCOORD_0", 2, vertices, where);
    any_uvs_ = any_uvs_ || !uv.empty();
    int colour_width = 0;  // COLOR_0 is RGB or RGBA (alpha unused)
    const std::vector<double> colour = attribute(p, "COLOR_0", 0, vertices, where, &colour_width);
    any_colours_ = any_colours_ || !colour.empty();
    const glm::dmat3 normal_matrix = glm::transpose(glm::inverse(glm::dmat3(world)));
    const auto base = static_cast<std::uint32_t>(positions_.size());
    for (std::size_t v = 0; v < vertices; ++v)
        positions_.push_back(
            glm::dvec3(world * glm::dvec4(xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2], 1.0)));
    const std::uint32_t material =
        p.material >= 0 ? static_cast<std::uint32_t>(p.material) : kNoFileMaterial;
    const std::vector<std::uint32_t> corners = triangle_corners(index, p.mode);
    TriangleMesh& mesh = scene_.geometry.mesh;
    for (std::size_t c = 0; c + 2 < corners.size(); c += 3) {
        mesh.triangles.push_back({base + corners[c], base + corners[c + 1], base + corners[c + 2]});
        mesh.materials.push_back(material);
        has_normals_.push_back(!normals.empty());
        for (int k = 0; k < 3; ++k) {
            const std::size_t v = corners[c + static_cast<std::size_t>(k)];
            uvs_.push_back(uv.empty() ? glm::vec2(0.0f) : glm::vec2(uv[2 * v], uv[2 * v + 1]));
            const std::size_t c0 = v * static_cast<std::size_t>(colour_width);
            colours_.push_back(colour.empty()
                                   ? vec3(1.0f)
                                   : glm::clamp(vec3(colour[c0], colour[c0 + 1], colour[c0 + 2]),
                                                vec3(0.0f), vec3(1.0f)));
            normals_.push_back(normals.empty()
                                   ? glm::dvec3(0.0)
                                   : normal_matrix * glm::dvec3(normals[3 * v], normals[3 * v + 1],
                                                                normals[3 * v + 2]));
        }
    }
    if (p.material >= static_cast<int>(model_.materials.size()))
        fail(where + "/material", "no such material " + std::to_string(p.material));
}

void GltfReader::add_camera(int camera, const glm::dmat4& world, const std::string& where) {
    if (camera >= static_cast<int>(model_.cameras.size()))
        fail(where + "/camera", "no such camera " + std::to_string(camera));
    const tinygltf::Camera& c = model_.cameras[static_cast<std::size_t>(camera)];
    if (c.type != "perspective") {
        warn(at("cameras", camera), "a " + c.type + " camera: only perspective ones are used");
        return;
    }
    const double yfov = glm::degrees(c.perspective.yfov);
    if (!(yfov > 0.01 && yfov < 179.0))
        fail(at("cameras", camera) + "/perspective/yfov", "out of range");
    GltfCamera cam;
    cam.name = c.name.empty() ? "camera " + std::to_string(camera) : c.name;
    cam.forward = vec3(glm::normalize(glm::dmat3(world) * glm::dvec3(0.0, 0.0, -1.0)));
    cam.up = vec3(glm::normalize(glm::dmat3(world) * glm::dvec3(0.0, 1.0, 0.0)));
    if (!std::isfinite(cam.forward.x) || !std::isfinite(cam.up.x))
        fail(where, "the camera's transform is singular");
    cam.yfov_degrees = static_cast<float>(yfov);
    cam.aspect = static_cast<float>(c.perspective.aspectRatio);
    camera_eyes_.push_back(glm::dvec3(world[3]));
    scene_.cameras.push_back(cam);
}

void GltfReader::add_light(const tinygltf::Value& ext, const glm::dmat4& world,
                           const std::string& where) {
    if (!ext.Has("light") || !ext.Get("light").IsInt()) return;
    const int index = ext.Get("light").Get<int>();
    if (index < 0 || index >= static_cast<int>(model_.lights.size()))
        fail(where + "/extensions/KHR_lights_punctual/light",
             "no such light " + std::to_string(index));
    const tinygltf::Light& l = model_.lights[static_cast<std::size_t>(index)];
    PendingLight p{Light{}, glm::dvec3(world[3]), std::max(l.intensity, 0.0)};
    if (l.color.size() == 3) p.light.colour = vec3(l.color[0], l.color[1], l.color[2]);
    if (l.type == "directional") {
        p.light.type = Light::Type::kDirectional;
        p.light.direction = vec3(glm::normalize(glm::dmat3(world) * glm::dvec3(0.0, 0.0, -1.0)));
    } else if (l.type == "spot") {
        warn("/extensions/KHR_lights_punctual/lights/" + std::to_string(index),
             "a spot light, lit as a point light (no cone)");
    }
    lights_.push_back(p);
}

// glTF's metallic-roughness material as the tutorial's Phong terms (docs/scene-format.md).
// The base colour texture `index` as one of the MeshFile's textures (read once).
std::uint32_t GltfReader::texture(int index, const std::string& where) {
    if (const auto known = texture_of_.find(index); known != texture_of_.end())
        return known->second;
    if (index < 0 || index >= static_cast<int>(model_.textures.size()))
        fail(where, "no such texture " + std::to_string(index));
    const tinygltf::Texture& t = model_.textures[static_cast<std::size_t>(index)];
    if (t.source < 0 || t.source >= static_cast<int>(model_.images.size()))
        fail(at("textures", index), "no image (or one the file does not have)");
    const tinygltf::Image& image = model_.images[static_cast<std::size_t>(t.source)];
    const std::string image_where = at("images", t.source);
    std::string extension = image.mimeType == "image/jpeg"  ? ".jpg"
                            : image.mimeType == "image/png" ? ".png"
                                                            : lower_extension(image.uri);
    if (extension.empty() || extension.size() > 5) extension = ".png";
    Texture texture = decode_texture(image.image, extension, file_, image_where);
    if (t.sampler >= 0 && t.sampler < static_cast<int>(model_.samplers.size())) {
        const tinygltf::Sampler& s = model_.samplers[static_cast<std::size_t>(t.sampler)];
        texture.wrap_u = wrap_mode(s.wrapS);
        texture.wrap_v = wrap_mode(s.wrapT);
    }
    const auto slot = static_cast<std::uint32_t>(scene_.geometry.textures.size());
    scene_.geometry.textures.push_back(std::move(texture));
    texture_of_[index] = slot;
    return slot;
}

Material GltfReader::material(int index) {
    const tinygltf::Material& g = model_.materials[static_cast<std::size_t>(index)];
    Material m = phong_of(g);
    if (m.name.empty()) m.name = "material " + std::to_string(index);
    const tinygltf::TextureInfo& base = g.pbrMetallicRoughness.baseColorTexture;
    if (base.index >= 0) {
        if (base.texCoord != 0)
            warn(at("materials", index),
                 "texture coordinates other than TEXCOORD_0: TEXCOORD_0 used");
        m.texture =
            texture(base.index, at("materials", index) + "/pbrMetallicRoughness/baseColorTexture");
    }
    return m;
}

// Positions to float relative to the origin; normals; lights scaled; cameras placed.
void GltfReader::finish() {
    MeshFile& g = scene_.geometry;
    glm::dvec3 lo(INFINITY), hi(-INFINITY);
    for (const glm::dvec3& p : positions_) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            fail("/accessors", "a position is not a finite number");
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const glm::dvec3 centre = positions_.empty() ? glm::dvec3(0.0) : 0.5 * (lo + hi);
    g.origin = mesh_origin(options_, lo, hi);
    g.scale = mesh_scale(options_, lo, hi);
    const auto stored = [&](const glm::dvec3& p) { return vec3((p - g.origin) / g.scale); };
    for (const glm::dvec3& p : positions_) g.mesh.positions.push_back(stored(p));
    if (std::find(has_normals_.begin(), has_normals_.end(), true) != has_normals_.end()) {
        for (std::size_t t = 0; t < g.mesh.triangles.size(); ++t) {
            const vec3 face = glm::normalize(g.mesh.face_normal(static_cast<std::uint32_t>(t)));
            for (int k = 0; k < 3; ++k) {
                const glm::dvec3 n = normals_[3 * t + static_cast<std::size_t>(k)];
                g.mesh.corner_normals.push_back(has_normals_[t] && glm::length(n) > 0.0
                                                    ? vec3(glm::normalize(n))
                                                    : face);  // flat where the file gives none
            }
        }
    }
    if (any_uvs_) g.mesh.corner_uvs = std::move(uvs_);
    if (any_colours_) g.mesh.corner_colours = std::move(colours_);
    for (std::size_t i = 0; i < scene_.cameras.size(); ++i)
        scene_.cameras[i].eye = stored(camera_eyes_[i]);
    double brightest = 0.0;
    std::vector<double> strength;
    for (const PendingLight& p : lights_) {
        const double d2 = glm::dot(p.position - centre, p.position - centre);
        strength.push_back(p.light.type == Light::Type::kDirectional
                               ? p.intensity
                               : p.intensity / std::max(d2, 1e-12));
        brightest = std::max(brightest, strength.back());
    }
    for (std::size_t i = 0; i < lights_.size(); ++i) {
        Light l = lights_[i].light;
        l.position = stored(lights_[i].position);
        l.colour *= brightest > 0.0 ? static_cast<float>(strength[i] / brightest) : 0.0f;
        scene_.lights.push_back(l);
    }
    if (skipped_primitives_ > 0)
        warn("/meshes", std::to_string(skipped_primitives_) +
                            " primitives of points or lines skipped (the tracer renders surfaces)");
}

GltfScene GltfReader::read() {
    parse();
    check_extensions();
    std::vector<int> path;
    for (int root : root_nodes()) walk(root, glm::dmat4(1.0), path);
    for (std::size_t i = 0; i < model_.materials.size(); ++i)
        scene_.geometry.materials.push_back(material(static_cast<int>(i)));
    finish();
    return std::move(scene_);
}

}  // namespace

GltfScene load_gltf(const std::filesystem::path& path, const MeshFileOptions& options) {
    return GltfReader(path, options).read();
}

}  // namespace rt
