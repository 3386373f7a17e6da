#include "app/gl/program.h"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <span>
#include <sstream>

#include <glm/gtc/type_ptr.hpp>

#include "core/error.h"

namespace rt::gl {
namespace {

std::string read_source(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in)
        throw Error(file.string(), "open", "cannot read the shader (is RTVIEW_SHADER_DIR right?)");
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

std::string info_log(GLuint object, bool is_program) {
    GLint length = 0;
    is_program ? glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length)
               : glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
    is_program ? glGetProgramInfoLog(object, length, nullptr, log.data())
               : glGetShaderInfoLog(object, length, nullptr, log.data());
    return log.c_str();
}

// Mesa writes "0:12(5): error: syntax error, ..."; keep the first error as line and text.
[[noreturn]] void compile_failed(const std::filesystem::path& file, const std::string& log) {
    static const std::regex first_error(R"((\d+):(\d+)\((\d+)\): error: ([^\n]*))");
    std::smatch m;
    if (std::regex_search(log, m, first_error))
        throw Error(file.string(), "line " + m[2].str(), m[4].str());
    const std::string first_line = log.substr(0, log.find('\n'));
    throw Error(file.string(), "compile",
                first_line.empty() ? "the shader does not compile" : first_line);
}

// The definitions go after the #version line, and #line puts the file's own line
// numbers back for the compiler's messages.
std::string with_defines(std::string source, const std::vector<std::string>& defines) {
    if (defines.empty()) return source;
    std::size_t at = 0;  // after the #version line, if there is one
    int next_line = 1;
    if (source.rfind("#version", 0) == 0) {
        at = std::min(source.find('\n'), source.size());
        source.insert(at, at == source.size() ? "\n" : "");
        at += 1;
        next_line = 2;
    }
    std::string lines;
    for (const std::string& d : defines) lines += "#define " + d + "\n";
    lines += "#line " + std::to_string(next_line) + "\n";
    return source.insert(at, lines);
}

ShaderHandle compile(GLenum stage, const std::filesystem::path& file,
                     const std::vector<std::string>& defines) {
    const std::string source = with_defines(read_source(file), defines);
    ShaderHandle shader(glCreateShader(stage));
    const char* text = source.c_str();
    glShaderSource(shader.get(), 1, &text, nullptr);
    glCompileShader(shader.get());
    GLint ok = GL_FALSE;
    glGetShaderiv(shader.get(), GL_COMPILE_STATUS, &ok);
    if (!ok) compile_failed(file, info_log(shader.get(), false));
    return shader;
}

// The stages linked into one program; a link error names `file`.
ProgramHandle link(std::span<const ShaderHandle> stages, const std::filesystem::path& file) {
    ProgramHandle program(glCreateProgram());
    for (const ShaderHandle& stage : stages) glAttachShader(program.get(), stage.get());
    glLinkProgram(program.get());
    GLint ok = GL_FALSE;
    glGetProgramiv(program.get(), GL_LINK_STATUS, &ok);
    if (!ok) {
        const std::string log = info_log(program.get(), true);
        throw Error(file.string(), "link", log.substr(0, log.find('\n')));
    }
    return program;
}

}  // namespace

Program::Program(const std::filesystem::path& vertex_file,
                 const std::filesystem::path& fragment_file,
                 const std::vector<std::string>& defines) {
    const std::array<ShaderHandle, 2> stages{compile(GL_VERTEX_SHADER, vertex_file, defines),
                                             compile(GL_FRAGMENT_SHADER, fragment_file, defines)};
    id_ = link(stages, fragment_file);
}

Program::Program(const std::filesystem::path& compute_file,
                 const std::vector<std::string>& defines) {
    const std::array<ShaderHandle, 1> stages{compile(GL_COMPUTE_SHADER, compute_file, defines)};
    id_ = link(stages, compute_file);
}

Program& ProgramVariants::get(const std::vector<std::string>& defines) {
    auto it = programs_.find(defines);
    if (it == programs_.end())
        it = programs_.try_emplace(defines, vertex_, fragment_, defines).first;
    return it->second;
}

GLint Program::location(const char* name) {
    const auto it = locations_.find(name);
    if (it != locations_.end()) return it->second;
    const GLint at =
        glGetUniformLocation(id_.get(), name);  // -1 (ignored by glUniform) if optimised away
    locations_.emplace(name, at);
    return at;
}

void Program::set(const char* name, int value) { glUniform1i(location(name), value); }
void Program::set(const char* name, unsigned value) { glUniform1ui(location(name), value); }
void Program::set(const char* name, float value) { glUniform1f(location(name), value); }
void Program::set(const char* name, const glm::vec3& value) {
    glUniform3fv(location(name), 1, glm::value_ptr(value));
}
void Program::set(const char* name, const glm::ivec2& value) {
    glUniform2iv(location(name), 1, glm::value_ptr(value));
}
void Program::set(const char* name, const glm::mat3& value) {
    glUniformMatrix3fv(location(name), 1, GL_FALSE, glm::value_ptr(value));
}
void Program::set(const char* name, const glm::mat4& value) {
    glUniformMatrix4fv(location(name), 1, GL_FALSE, glm::value_ptr(value));
}

}  // namespace rt::gl
