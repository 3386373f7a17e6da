#pragma once
// A GLSL program built from two files in shaders/ (or one compute shader). Compile and link errors
// become rt::Error "shaders/phong.frag: line 12: syntax error, unexpected ...".
//
// A program may be compiled with preprocessor definitions ("SHADOW_MAPS 1"), so that one
// file serves as several specialised programs. On llvmpipe this is what makes a switched
// off feature free: it runs every side of a branch under a mask, even a branch on a
// uniform that every fragment takes the same way.

#include <filesystem>
#include <map>
#include <string>
#include <unordered_map>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "app/common/data_dir.h"
#include "app/gl/gl.h"
#include "app/gl/handle.h"

namespace rt::gl {

// Where shaders are read from (app/common/data_dir.h).
using rt::app::shader_dir;

class Program {
  public:
    Program(const std::filesystem::path& vertex_file, const std::filesystem::path& fragment_file,
            const std::vector<std::string>& defines = {});
    // A compute program (OpenGL 4.3) from one file.
    explicit Program(const std::filesystem::path& compute_file,
                     const std::vector<std::string>& defines = {});

    void use() const { glUseProgram(id_.get()); }
    void set(const char* name, int value);
    void set(const char* name, unsigned value);
    void set(const char* name, float value);
    void set(const char* name, const glm::vec3& value);
    void set(const char* name, const glm::ivec2& value);
    void set(const char* name, const glm::mat3& value);
    void set(const char* name, const glm::mat4& value);

  private:
    GLint location(const char* name);

    ProgramHandle id_;
    std::unordered_map<std::string, GLint> locations_;
};

// One pair of shader files compiled once per set of definitions, when first asked for.
class ProgramVariants {
  public:
    ProgramVariants(std::filesystem::path vertex_file, std::filesystem::path fragment_file)
        : vertex_(std::move(vertex_file)), fragment_(std::move(fragment_file)) {}

    Program& get(const std::vector<std::string>& defines);

  private:
    std::filesystem::path vertex_;
    std::filesystem::path fragment_;
    std::map<std::vector<std::string>, Program> programs_;
};

}  // namespace rt::gl
