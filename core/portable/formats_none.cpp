// The portable build (RTVIEW_PORTABLE_BENCH: rtbench for a machine with a GPU driver and
// nothing else): no OpenImageIO, tinygltf or Assimp beneath it. What needs them says so
// in one located line instead.
#include "core/assimp_loader.h"
#include "core/error.h"
#include "core/gltf_loader.h"
#include "core/image.h"

namespace rt {
namespace {

const char* const kWhy = "this is the portable build (RTVIEW_PORTABLE_BENCH), which has no ";

}  // namespace

bool is_supported_output(const std::filesystem::path&) { return false; }

void write_image(const Image&, const std::filesystem::path& path) {
    throw Error(path.string(), "output", std::string(kWhy) + "image files");
}

Image read_image(const std::filesystem::path& path) {
    throw Error(path.string(), "image", std::string(kWhy) + "image files");
}

GltfScene load_gltf(const std::filesystem::path& path, const MeshFileOptions&) {
    throw Error(path.string(), "glTF", std::string(kWhy) + "glTF reader");
}

MeshFile load_ply_stl(const std::filesystem::path& path, const MeshFileOptions&) {
    throw Error(path.string(), "mesh", std::string(kWhy) + "PLY and STL reader");
}

}  // namespace rt
