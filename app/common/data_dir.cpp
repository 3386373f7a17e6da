#include "app/common/data_dir.h"

#include <cstdlib>
#include <system_error>

namespace rt::app {
namespace {

std::filesystem::path find(const char* variable, const char* name) {
    if (const char* env = std::getenv(variable); env && *env) return env;
    const std::filesystem::path here = program_dir();
    std::error_code ec;
    for (const std::filesystem::path& candidate :
         {here / ".." / "share" / "rtview" / name, here / ".." / ".." / "share" / "rtview" / name,
          here / name}) {
        if (!here.empty() && std::filesystem::is_directory(candidate, ec))
            return std::filesystem::weakly_canonical(candidate, ec);
    }
    // None: the installed layout's, so that "cannot read" names where it should be.
    return here.empty() ? std::filesystem::path(name)
                        : (here / ".." / "share" / "rtview" / name).lexically_normal();
}

}  // namespace

std::filesystem::path program_dir() {
    std::error_code ec;
    const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    return ec ? std::filesystem::path() : exe.parent_path();
}

std::filesystem::path shader_dir() { return find("RTVIEW_SHADER_DIR", "shaders"); }
std::filesystem::path asset_dir() { return find("RTVIEW_ASSET_DIR", "assets"); }

}  // namespace rt::app
