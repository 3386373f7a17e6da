#pragma once
// A GLSL program built from two files in shaders/. Compile and link errors become
// rt::Error "shaders/phong.frag: line 12: syntax error, unexpected ...".

#include <filesystem>
#include <string>
#include <unordered_map>

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "app/gl/gl.h"
#include "app/gl/handle.h"

namespace rt::gl {

// Where shaders are read from: $RTVIEW_SHADER_DIR if set, else the source tree's
// shaders/ as baked in at build time.
std::filesystem::path shader_dir();

class Program {
  public:
    Program(const std::filesystem::path& vertex_file, const std::filesystem::path& fragment_file);

    void use() const { glUseProgram(id_.get()); }
    void set(const char* name, int value);
    void set(const char* name, unsigned value);
    void set(const char* name, float value);
    void set(const char* name, const glm::vec3& value);
    void set(const char* name, const glm::mat3& value);
    void set(const char* name, const glm::mat4& value);

  private:
    GLint location(const char* name);

    ProgramHandle id_;
    std::unordered_map<std::string, GLint> locations_;
};

}  // namespace rt::gl
