#version 330 core
// A mesh's lines and points (OBJ `l` and `p`): drawn by the raster view only, in the
// material's diffuse colour, unlit (a line has no normal to light). The tracer renders
// surfaces and does not see them; the difference view shows them as such.

uniform vec3 u_colour;

layout(location = 0) out vec4 o_colour;

void main() { o_colour = vec4(u_colour, 1.0); }
