#pragma once
// glTF 2.0 (.gltf with embedded or separate buffers, and .glb) through tinygltf: the
// default scene's node hierarchy flattened into one triangle mesh in scene coordinates
// (matrices and TRS, in double), its materials mapped onto the tutorial's (the table and
// formulas are in docs/scene-format.md), its perspective cameras and its
// KHR_lights_punctual lights. Everything it cannot use is refused with a located
// "FILE: WHERE: WHAT" error (a missing buffer, an accessor out of its buffer, a required
// extension) or skipped with a warning line (points and lines, orthographic cameras,
// unknown extensions).

#include <filesystem>
#include <string>
#include <vector>

#include "core/light.h"
#include "core/mesh_file.h"

namespace rt {

// A perspective camera as the node that holds it places it: it looks down the node's -z
// with +y up.
struct GltfCamera {
    std::string name;
    vec3 eye{0.0f};  // relative to MeshFile::origin, in units of MeshFile::scale, like the mesh
    vec3 forward{0.0f, 0.0f, -1.0f};
    vec3 up{0.0f, 1.0f, 0.0f};
    float yfov_degrees = 40.0f;
    float aspect = 0.0f;  // width / height, 0 where the file gives none
};

struct GltfScene {
    MeshFile geometry;
    std::vector<GltfCamera> cameras;  // in the order the hierarchy is walked
    // Point and directional lights (spot lights as point lights, with a warning). Their
    // colours keep the lights' relative strengths as seen from the middle of the mesh,
    // the brightest at 1: Phong without fall-off has no unit for a candela.
    std::vector<Light> lights;
};

GltfScene load_gltf(const std::filesystem::path& path, const MeshFileOptions& options = {});

}  // namespace rt
