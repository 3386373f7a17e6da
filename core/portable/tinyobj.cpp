// The portable build compiles tinyobjloader in (Debian's is a shared library).
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>
