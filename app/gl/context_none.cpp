// The portable build (RTVIEW_PORTABLE_BENCH) has EGL only: no OSMesa beneath it.
#include <stdexcept>

#include "app/gl/context.h"

namespace rt::gl::detail {

std::unique_ptr<Context> create_osmesa_context() {
    throw std::runtime_error("this is the portable build (RTVIEW_PORTABLE_BENCH), without OSMesa");
}

}  // namespace rt::gl::detail
