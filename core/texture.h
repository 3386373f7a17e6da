#pragma once
// An image on a surface: the base colour texture of a glTF material or an MTL's map_Kd.
// Both pipelines sample it the same way (the rule, in docs/scene-format.md): bilinear
// between the four texels around the point, at full resolution (no mipmaps: the GL side
// samples level 0 too), in linear colour (the file's sRGB decoded per texel, as GL's
// SRGB8 textures do before filtering), texel centres at (i + 1/2) / size, with the
// material's wrap mode per axis. Texture coordinates follow glTF: (0, 0) is the image's
// top left corner, v grows downwards (an OBJ's vt is flipped on reading).

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "core/ray.h"

namespace rt {

enum class Wrap { kRepeat, kClamp, kMirror };  // GL's REPEAT, CLAMP_TO_EDGE, MIRRORED_REPEAT

struct Texture {
    std::string name;  // the file, or "FILE: /images/N", for messages
    int width = 0, height = 0;
    std::vector<vec3> texels;  // linear, row 0 the top
    Wrap wrap_u = Wrap::kRepeat, wrap_v = Wrap::kRepeat;

    vec3 at(int x, int y) const { return texels[static_cast<std::size_t>(y) * width + x]; }
    vec3 sample(glm::vec2 uv) const;
};

// A texel index wrapped into [0, size).
int wrap_texel(int i, int size, Wrap mode);

// Image files as textures, through the reader a program is linked with: rt_image_io
// (core/image_io.cpp, OpenImageIO) installs its own; a program without it (rtbench, which
// needs geometry only) reads none, and a texture there is one located line saying so.
// Errors are rt::Error naming `file` (the scene or mesh file that refers to the image)
// and `where` in it.
Texture read_texture(const std::filesystem::path& path, const std::string& file,
                     const std::string& where);
// An image held in memory (a .glb's or a data URI's), of the format `extension` names.
Texture decode_texture(const std::vector<unsigned char>& bytes, const std::string& extension,
                       const std::string& file, const std::string& where);

struct ImageReader {
    Texture (*read)(const std::filesystem::path& path, const std::string& file,
                    const std::string& where) = nullptr;
    Texture (*decode)(const std::vector<unsigned char>& bytes, const std::string& extension,
                      const std::string& file, const std::string& where) = nullptr;
};
void install_image_reader(const ImageReader& reader);

}  // namespace rt
