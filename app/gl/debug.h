#pragma once
// GL errors are never silent: KHR_debug output (in debug builds, or with
// RTVIEW_GL_DEBUG=1) prints every message and counts the errors; check() asks
// glGetError in every build and throws.

#include <cstdint>

namespace rt::gl {

bool debug_output_requested();
// Hooks the KHR_debug callback into the current context if it was requested; returns
// (and debug_output_installed() then tells) whether it is in place.
bool install_debug_output();
bool debug_output_installed();
// Errors (and undefined-behaviour reports) seen by the callback since start-up.
std::uint64_t debug_error_count();
// Throws std::runtime_error naming `where` if glGetError has anything to say.
void check(const char* where);

}  // namespace rt::gl
