#include "core/mesh_file.h"

#include <algorithm>
#include <cmath>

#include "core/assimp_loader.h"
#include "core/error.h"
#include "core/file_kind.h"
#include "core/gltf_loader.h"
#include "core/obj_loader.h"

namespace rt {

glm::dvec3 mesh_origin(const MeshFileOptions& options, const glm::dvec3& lo, const glm::dvec3& hi) {
    if (options.origin) return *options.origin;
    if (!(lo.x <= hi.x)) return glm::dvec3(0.0);  // nothing used
    const glm::dvec3 centre = 0.5 * (lo + hi);
    const double far = std::max({std::fabs(centre.x), std::fabs(centre.y), std::fabs(centre.z)});
    const glm::dvec3 side = hi - lo;
    const double size = std::max({side.x, side.y, side.z});
    const bool small_for_its_place = size > 0.0 && far > options.recentre_beyond_sizes * size;
    return far > options.recentre_beyond || small_for_its_place ? centre : glm::dvec3(0.0);
}

double power_of_two_unit(double size) {
    if (!(size > 0.0) || !std::isfinite(size)) return 1.0;
    if (size >= kSmallestSize && size <= kLargestSize) return 1.0;
    int exponent = 0;
    std::frexp(size, &exponent);  // size = m 2^exponent, m in [0.5, 1)
    return std::ldexp(1.0, exponent - 1);
}

double mesh_scale(const MeshFileOptions& options, const glm::dvec3& lo, const glm::dvec3& hi) {
    if (options.scale) return *options.scale;
    const glm::dvec3 side = hi - lo;
    return options.rescale ? power_of_two_unit(std::max({side.x, side.y, side.z})) : 1.0;
}

MeshFile load_mesh_file(const std::filesystem::path& path, const MeshFileOptions& options) {
    const std::string ext = lower_extension(path);
    if (ext == ".obj") return load_obj(path, options);
    if (ext == ".gltf" || ext == ".glb") return load_gltf(path, options).geometry;
    if (ext == ".ply" || ext == ".stl") return load_ply_stl(path, options);
    throw Error(path.string(), "open",
                "unknown mesh format \"" + ext + "\" (expected .obj, .gltf, .glb, .ply or .stl)");
}

}  // namespace rt
