#pragma once
// The one way into OpenGL: glad's generated 3.3 core loader (plus KHR_debug).
#include <glad/gl.h>
