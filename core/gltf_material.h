#pragma once
// glTF's metallic-roughness material as the tutorial's Phong terms: the table of
// docs/scene-format.md (textures are the loader's business, core/gltf_loader.cpp).

#include <tiny_gltf.h>

#include "core/material.h"

namespace rt {

Material phong_of(const tinygltf::Material& g);

}  // namespace rt
