#include "core/scene_loader.h"

#include <map>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "core/error.h"
#include "core/file_kind.h"
#include "core/gltf_loader.h"
#include "core/json_reader.h"
#include "core/mesh_file.h"
#include "core/obj_loader.h"
#include "core/scene_loader_shared.h"

namespace rt {
namespace {

using loader::append_textures;
using loader::kFarForItsSize;
using loader::kFarFromOrigin;
using loader::kMaxResolution;

double farthest(const glm::dvec3& p) {
    return std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
}

bool far_from_origin(const glm::dvec3& p) { return farthest(p) > kFarFromOrigin; }

// Walks one JSON scene into a SceneDescription, keeping the names and caches that loading needs.
class JsonSceneReader {
  public:
    // `size`: the scene's size in file units where its camera does not say it (one given
    // by u, v and n has no point it looks at), else 0.
    JsonSceneReader(std::filesystem::path path, LoadedScene& out, double size = 0.0)
        : path_(std::move(path)),
          file_(path_.string()),
          out_(out),
          scene_(out.scene),
          size_(size) {}

    void read(const nlohmann::json& doc) {
        const JsonValue root(doc, "", file_);
        root.keys(
            {"camera", "resolution", "background", "ambient", "lights", "materials", "objects"});
        // A scene far from the origin is read relative to its eye, in double precision,
        // so that float's precision follows the eye (what the rays and the raster see).
        const JsonValue camera = root["camera"];
        const glm::dvec3 eye = camera["eye"].dvector3();
        double size = size_;  // how far the camera looks: the scene's scale, where it says
        if (const auto look_at = camera.find("look_at"))
            size = glm::length(look_at->dvector3() - eye);
        if (far_from_origin(eye) || (size > 0.0 && farthest(eye) > kFarForItsSize * size))
            origin_ = eye;
        // A scene whose camera looks a distance float's arithmetic handles badly (core/
        // mesh_file.h) is read in units of a power of two, as a bare model is.
        unit_ = power_of_two_unit(size);
        out_.origin = origin_;
        out_.scale = unit_;
        scene_.origin = origin_ / unit_;
        read_materials(root.find("materials"));
        if (const auto bg = root.find("background")) scene_.background = bg->colour();
        if (const auto amb = root.find("ambient")) scene_.ambient = amb->colour();
        int cols = 640, rows = 480;
        if (const auto res = root.find("resolution")) {
            const auto wh = res->elements(2, 2);
            cols = wh[0].integer_between(1, kMaxResolution);
            rows = wh[1].integer_between(1, kMaxResolution);
        }
        scene_.camera = read_camera(root["camera"], cols, rows);
        if (const auto lights = root.find("lights"))
            for (const JsonValue& l : lights->elements()) scene_.lights.push_back(read_light(l));
        for (const JsonValue& o : root["objects"].elements()) read_object(o);
    }

  private:
    Camera read_camera(const JsonValue& j, int cols, int rows) const;
    Light read_light(const JsonValue& j) const;
    void read_materials(const std::optional<JsonValue>& j);
    Material read_material(const JsonValue& j, Material m) const;
    std::uint32_t material_index(const JsonValue& j) const;
    void read_object(const JsonValue& j);
    Shape read_mesh(const JsonValue& j, glm::dmat4& normalize);
    // A position in world coordinates, relative to the scene's origin, in its unit.
    vec3 point(const JsonValue& j) const { return vec3((j.dvector3() - origin_) / unit_); }
    // The mesh of a file, read once per file and placement: `in_world` reads it
    // relative to the scene's origin (an untransformed mesh's coordinates are the world's).
    std::uint32_t load_mesh(const JsonValue& file_value, bool in_world);

    std::filesystem::path path_;
    std::string file_;
    LoadedScene& out_;
    SceneDescription& scene_;
    std::map<std::string, std::uint32_t> material_names_;
    std::map<std::pair<std::filesystem::path, bool>, std::uint32_t> mesh_cache_;
    glm::dvec3 origin_{0.0};  // the file's coordinates of the scene's zero
    double unit_ = 1.0;       // file units per scene unit (LoadedScene::scale)
    double size_ = 0.0;
};

vec3 unit_vector(const JsonValue& j) {
    const vec3 v = j.vector3();
    const float len = glm::length(v);
    if (!(len > 0.0f) || !std::isfinite(len)) j.fail("must be a non-zero vector");
    return v / len;
}

Camera JsonSceneReader::read_camera(const JsonValue& j, int cols, int rows) const {
    j.keys({"eye", "look_at", "up", "fov", "u", "v", "n", "W", "H", "N"});
    const vec3 eye = point(j["eye"]);
    Camera cam;
    if (j.has("look_at")) {
        if (j.has("u") || j.has("v") || j.has("n"))
            j.fail("give either look_at and up, or u, v and n");
        const vec3 target = point(j["look_at"]);
        if (!(glm::length(target - eye) > 0.0f)) j["look_at"].fail("must differ from eye");
        const vec3 up = j.has("up") ? unit_vector(j["up"]) : vec3(0.0f, 1.0f, 0.0f);
        if (glm::length(glm::cross(up, glm::normalize(target - eye))) < 1e-4f)
            (j.has("up") ? j["up"] : j).fail("up is parallel to the viewing direction");
        const float fov = j.has("fov") ? j["fov"].number_between(0.01f, 179.0f) : 40.0f;
        cam = Camera::look_at(eye, target, up, fov, cols, rows);
    } else {
        cam.eye = eye;
        cam.u = unit_vector(j["u"]);
        cam.v = unit_vector(j["v"]);
        cam.n = unit_vector(j["n"]);
        if (std::fabs(glm::dot(cam.u, cam.v)) > 1e-3f ||
            std::fabs(glm::dot(cam.u, cam.n)) > 1e-3f || std::fabs(glm::dot(cam.v, cam.n)) > 1e-3f)
            j.fail("u, v and n must be orthogonal");
        if (glm::dot(glm::cross(cam.u, cam.v), cam.n) < 0.0f)
            j.fail("u, v and n must be right-handed (u x v = n)");
        cam.cols = cols;
        cam.rows = rows;
    }
    if (j.has("N") || j.has("H") || j.has("W")) {
        if (j.has("fov")) j.fail("give either fov, or the view plane W, H and N");
        cam.N = j.has("N") ? j["N"].number_above(0.0f) : 1.0f;
        cam.H = j["H"].number_above(0.0f);
        cam.W = j.has("W") ? j["W"].number_above(0.0f)
                           : cam.H * static_cast<float>(cols) / static_cast<float>(rows);
    } else if (!j.has("look_at")) {
        j.fail("a camera given by u, v and n needs the view plane H (and optionally W and N)");
    }
    return cam;
}

Light JsonSceneReader::read_light(const JsonValue& j) const {
    const std::string type = j["type"].string();
    Light light;
    if (type == "point") {
        j.keys({"type", "position", "color"});
        light.type = Light::Type::kPoint;
        light.position = point(j["position"]);
    } else if (type == "directional") {
        j.keys({"type", "direction", "color"});
        light.type = Light::Type::kDirectional;
        light.direction = unit_vector(j["direction"]);
    } else {
        j["type"].fail("unknown light type \"" + type + "\" (expected point or directional)");
    }
    if (const auto c = j.find("color")) light.colour = c->colour();
    return light;
}

void JsonSceneReader::read_materials(const std::optional<JsonValue>& j) {
    for (const Material& m : material_presets()) {
        material_names_[m.name] = static_cast<std::uint32_t>(scene_.materials.size());
        scene_.materials.push_back(m);
    }
    if (!j) return;
    for (const auto& [name, value] : j->members()) {
        Material m = read_material(value, Material{});
        m.name = name;
        const auto known = material_names_.find(name);
        if (known != material_names_.end()) {
            scene_.materials[known->second] = m;  // a scene may redefine a preset
        } else {
            material_names_[name] = static_cast<std::uint32_t>(scene_.materials.size());
            scene_.materials.push_back(m);
        }
    }
}

Material JsonSceneReader::read_material(const JsonValue& j, Material m) const {
    j.keys({"ka", "kd", "ks", "shininess", "reflectivity", "transparency", "ior", "emission",
            "checker"});
    if (const auto v = j.find("ka")) m.ka = v->colour();
    if (const auto v = j.find("kd")) m.kd = v->colour();
    if (const auto v = j.find("ks")) m.ks = v->colour();
    if (const auto v = j.find("shininess")) m.shininess = v->number_at_least(0.0f);
    if (const auto v = j.find("reflectivity")) m.reflectivity = v->number_between(0.0f, 1.0f);
    if (const auto v = j.find("transparency")) m.transparency = v->number_between(0.0f, 1.0f);
    if (const auto v = j.find("ior")) m.ior = v->number_above(0.0f);
    if (const auto v = j.find("emission")) m.emission = v->colour();
    if (const auto c = j.find("checker")) {
        c->keys({"colors", "scale"});
        const auto colours = (*c)["colors"].elements(2, 2);
        const double scale = c->has("scale") ? (*c)["scale"].number_above(0.0f) : 1.0f;
        m.checker =
            Checker{colours[0].colour(), colours[1].colour(), static_cast<float>(scale / unit_)};
    }
    return m;
}

std::uint32_t JsonSceneReader::material_index(const JsonValue& j) const {
    const std::string name = j.string();
    const auto it = material_names_.find(name);
    if (it != material_names_.end()) return it->second;
    std::string known;
    for (const auto& [n, index] : material_names_) known += (known.empty() ? "" : ", ") + n;
    j.fail("unknown material \"" + name + "\" (known: " + known + ")");
}

// Scale, then rotate (x, then y, then z, in degrees), then translate; or a 4x4 matrix
// given row by row. An array of these applies its elements in order. Double precision,
// so that a far-away translation and the scene's origin cancel exactly.
glm::dmat4 read_transform(const JsonValue& j) {
    if (j.is_array()) {
        glm::dmat4 m(1.0);
        for (const JsonValue& step : j.elements()) m = read_transform(step) * m;
        return m;
    }
    j.keys({"translate", "rotate", "scale", "matrix"});
    if (const auto mat = j.find("matrix")) {
        if (j.has("translate") || j.has("rotate") || j.has("scale"))
            j.fail("\"matrix\" cannot be combined with translate, rotate or scale");
        glm::dmat4 m;
        const auto rows = mat->elements(4, 4);
        for (int r = 0; r < 4; ++r) {
            const auto row = rows[r].elements(4, 4);
            for (int c = 0; c < 4; ++c) m[c][r] = row[c].number_double();
        }
        return m;
    }
    glm::dmat4 m(1.0);
    if (const auto s = j.find("scale"))
        m = glm::scale(glm::dmat4(1.0),
                       s->is_number() ? glm::dvec3(s->number_double()) : s->dvector3());
    if (const auto r = j.find("rotate")) {
        const glm::dvec3 deg = r->dvector3();
        for (int axis = 0; axis < 3; ++axis) {
            glm::dvec3 unit(0.0);
            unit[axis] = 1.0;
            m = glm::rotate(glm::dmat4(1.0), glm::radians(deg[axis]), unit) * m;
        }
    }
    if (const auto t = j.find("translate")) m = glm::translate(glm::dmat4(1.0), t->dvector3()) * m;
    return m;
}

void JsonSceneReader::read_object(const JsonValue& j) {
    const std::string type = j["type"].string();
    Object o;
    // Applied before the object's own transform: a mesh's normalisation, else the unit
    // (the shape's coordinates were divided by it, the transform expects the file's).
    glm::dmat4 pre = glm::scale(glm::dmat4(1.0), glm::dvec3(unit_));
    // A shape with a transform is given in its own coordinates, which the transform
    // places; one without is given in world coordinates, taken relative to the origin.
    // A mesh that is moved (a transform, or normalize) is placed by its transform; one
    // that is not has its file read relative to the origin, in double precision.
    const bool placed =
        j.has("transform") || (type == "mesh" && j.has("normalize") && j["normalize"].boolean());
    // Every length is read in the scene's unit (unit_), a shape's own coordinates too,
    // so that the transform's linear part stays as the file gives it.
    const auto position = [&](const JsonValue& v) {
        return placed ? vec3(v.dvector3() / unit_) : point(v);
    };
    if (type == "sphere") {
        j.keys({"type", "name", "material", "transform", "center", "radius"});
        const double radius = j.has("radius") ? j["radius"].number_above(0.0f) : 1.0f;
        o.shape = Sphere{j.has("center") ? position(j["center"])
                                         : vec3(placed ? glm::dvec3(0.0) : -origin_ / unit_),
                         static_cast<float>(radius / unit_)};
    } else if (type == "plane") {
        j.keys({"type", "name", "material", "transform", "normal", "offset", "point"});
        const vec3 n = unit_vector(j["normal"]);
        if (j.has("offset") && j.has("point")) j.fail("give either offset or point, not both");
        // n . x = offset, and with x = x' + origin: n . x' = offset - n . origin.
        const glm::dvec3 shift = placed ? glm::dvec3(0.0) : origin_;
        const double offset = j.has("point")
                                  ? glm::dot(j["point"].dvector3(), glm::dvec3(n))
                                  : (j.has("offset") ? j["offset"].number_double() : 0.0);
        o.shape = Plane{n, static_cast<float>((offset - glm::dot(shift, glm::dvec3(n))) / unit_)};
    } else if (type == "triangle") {
        j.keys({"type", "name", "material", "transform", "vertices"});
        const auto v = j["vertices"].elements(3, 3);
        const Triangle tri{position(v[0]), position(v[1]), position(v[2])};
        if (!(glm::length(glm::cross(tri.b - tri.a, tri.c - tri.a)) > 0.0f))
            j["vertices"].fail("the vertices are collinear (the triangle has no area)");
        o.shape = tri;
    } else if (type == "mesh") {
        j.keys({"type", "name", "material", "transform", "file", "normalize"});
        o.shape = read_mesh(j, pre);
    } else {
        j["type"].fail("unknown object type \"" + type +
                       "\" (expected sphere, plane, triangle or mesh)");
    }
    o.name = j.has("name") ? j["name"].string()
                           : type + " " + j.pointer().substr(j.pointer().rfind('/') + 1);
    o.material = j.has("material") ? material_index(j["material"]) : material_names_.at("default");
    const glm::dmat4 placement =
        (j.has("transform") ? read_transform(j["transform"]) : glm::dmat4(1.0)) * pre;
    const glm::mat4 m = placed ? glm::mat4(glm::scale(glm::dmat4(1.0), glm::dvec3(1.0 / unit_)) *
                                           glm::translate(glm::dmat4(1.0), -origin_) * placement)
                               : glm::mat4(1.0f);
    if (m != glm::mat4(1.0f)) {
        o.transform = Transform::from_matrix(m);
        if (!o.transform)
            (j.has("transform") ? j["transform"] : j)
                .fail("the transform is singular (or not affine)");
    }
    scene_.objects.push_back(std::move(o));
}

Shape JsonSceneReader::read_mesh(const JsonValue& j, glm::dmat4& normalize) {
    const bool normalized = j.has("normalize") && j["normalize"].boolean();
    const std::uint32_t index = load_mesh(j["file"], !j.has("transform") && !normalized);
    if (j.has("normalize") && j["normalize"].boolean()) {
        // Largest side 1, centred on x and z, resting on y = 0.
        const Aabb b = bounds_of(scene_.meshes[index]);
        const vec3 e = b.extent();
        const float largest = std::max({e.x, e.y, e.z});
        if (!(largest > 0.0f)) j["normalize"].fail("the mesh has no extent to normalise");
        const vec3 anchor{b.centre().x, b.lo.y, b.centre().z};
        normalize = glm::scale(glm::dmat4(1.0), glm::dvec3(1.0 / largest)) *
                    glm::translate(glm::dmat4(1.0), -glm::dvec3(anchor));
    }
    return MeshRef{index, !j.has("material")};
}

std::uint32_t JsonSceneReader::load_mesh(const JsonValue& file_value, bool in_world) {
    const std::filesystem::path mesh_path = path_.parent_path() / file_value.string();
    const auto key = std::make_pair(mesh_path, in_world && origin_ != glm::dvec3(0.0));
    const auto cached = mesh_cache_.find(key);
    if (cached != mesh_cache_.end()) return cached->second;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(mesh_path, ec))
        file_value.fail("cannot open mesh file \"" + mesh_path.string() + "\"");
    MeshFileOptions options;
    if (key.second) options.origin = origin_;
    options.scale = unit_;
    MeshFile obj = load_mesh_file(mesh_path, options);
    const auto first_material = static_cast<std::uint32_t>(scene_.materials.size());
    append_textures(obj, scene_);
    for (Material& m : obj.materials) {
        m.name = mesh_path.filename().string() + ":" + m.name;
        scene_.materials.push_back(std::move(m));
    }
    const std::uint32_t fallback = material_names_.at("default");
    for (std::uint32_t& m : obj.mesh.materials)
        m = m < obj.materials.size() ? first_material + m : fallback;
    out_.warnings.insert(out_.warnings.end(), obj.warnings.begin(), obj.warnings.end());
    const auto index = static_cast<std::uint32_t>(scene_.meshes.size());
    scene_.meshes.push_back(std::move(obj.mesh));
    mesh_cache_[key] = index;
    return index;
}

}  // namespace

std::vector<Material> material_presets() {
    Material standard;  // default: grey plastic
    standard.ka = vec3(0.2f);
    standard.kd = vec3(0.7f);
    standard.ks = vec3(0.3f);
    Material matte = standard;
    matte.name = "matte";
    matte.ks = vec3(0.0f);
    Material mirror;
    mirror.name = "mirror";
    mirror.ka = vec3(0.0f);
    mirror.kd = vec3(0.05f);
    mirror.ks = vec3(0.8f);
    mirror.shininess = 200.0f;
    mirror.reflectivity = 0.9f;
    Material glass = mirror;
    glass.name = "glass";
    glass.reflectivity = 0.1f;
    glass.transparency = 0.9f;
    glass.ior = 1.5f;
    return {standard, matte, mirror, glass};
}

namespace {

// The largest side of the box around a scene's eye, point lights and bounded objects (in
// its own units; planes and directional lights have no place).
double content_size(const SceneDescription& scene) {
    Aabb box;
    box.grow(scene.camera.eye);
    for (const Light& l : scene.lights)
        if (l.type == Light::Type::kPoint) box.grow(l.position);
    for (const Object& o : scene.objects) {
        const Aabb b =
            std::visit(Overloaded{[&](const MeshRef& m) { return bounds_of(scene.meshes[m.mesh]); },
                                  [](const auto& shape) { return Aabb(shape.bounds()); }},
                       o.shape);
        if (!b.empty()) box.grow(o.transform ? b.transformed(o.transform->m) : b);
    }
    const vec3 side = box.extent();
    return std::max({side.x, side.y, side.z});
}

}  // namespace

LoadedScene load_json_scene(const std::filesystem::path& path) {
    const nlohmann::json doc = parse_json_file(path);
    LoadedScene out;
    JsonSceneReader(path, out).read(doc);
    // A camera given by u, v and n does not say how large the scene is: where what the
    // first reading holds is of a size float handles badly, or lies far away for its
    // size, the file is read again knowing its size (its unit and origin follow from it,
    // as from a look_at camera's distance).
    if (doc.at("camera").contains("look_at")) return out;  // read() checked the camera
    const double size = content_size(out.scene) * out.scale;
    const glm::dvec3 eye = out.origin + glm::dvec3(out.scene.camera.eye) * out.scale;
    const bool far =
        out.origin == glm::dvec3(0.0) && size > 0.0 && farthest(eye) > kFarForItsSize * size;
    if (power_of_two_unit(size) == 1.0 && !far) return out;
    LoadedScene again;
    JsonSceneReader(path, again, size).read(doc);
    return again;
}

bool is_bare_mesh(const std::filesystem::path& path) {
    const std::string ext = lower_extension(path);
    return ext == ".obj" || ext == ".ply" || ext == ".stl";
}

bool is_scene_file(const std::filesystem::path& path) {
    const std::string ext = lower_extension(path);
    return is_bare_mesh(path) || ext == ".json" || ext == ".gltf" || ext == ".glb";
}

LoadedScene load_scene(const std::filesystem::path& path, const LoadOptions& options) {
    const std::string ext = lower_extension(path);
    if (ext == ".obj") return load_obj_scene(path, options);
    if (ext == ".json") return load_json_scene(path);
    if (ext == ".gltf" || ext == ".glb") return load_gltf_scene(path, options);
    if (ext == ".ply" || ext == ".stl") return load_obj_scene(path, options);
    throw Error(path.string(), "open",
                "unknown scene format \"" + ext + "\" (expected " + kSceneFormats + ")");
}

}  // namespace rt
