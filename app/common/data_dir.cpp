#include "app/common/data_dir.h"

#include <cstdlib>

#include "core/program_dir.h"

namespace rt::app {
namespace {

std::filesystem::path find(const char* variable, const char* name) {
    if (const char* env = std::getenv(variable); env && *env) return env;
    return find_beside_program(std::filesystem::path("share") / "rtview" / name);
}

}  // namespace

std::filesystem::path shader_dir() { return find("RTVIEW_SHADER_DIR", "shaders"); }
std::filesystem::path asset_dir() { return find("RTVIEW_ASSET_DIR", "assets"); }

}  // namespace rt::app
