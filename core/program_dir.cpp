#include "core/program_dir.h"

#include <system_error>

namespace rt {

std::filesystem::path program_dir() {
    std::error_code ec;
    const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    return ec ? std::filesystem::path() : exe.parent_path();
}

std::filesystem::path find_beside_program(const std::filesystem::path& in_prefix) {
    const std::filesystem::path here = program_dir();
    if (here.empty()) return in_prefix.filename();
    std::error_code ec;
    for (const std::filesystem::path& candidate :
         {here / ".." / in_prefix, here / ".." / ".." / in_prefix, here / in_prefix.filename()}) {
        if (std::filesystem::exists(candidate, ec))
            return std::filesystem::weakly_canonical(candidate, ec);
    }
    return (here / ".." / in_prefix).lexically_normal();
}

}  // namespace rt
