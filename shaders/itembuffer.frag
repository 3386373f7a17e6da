#version 330 core
// The item buffer (Weghorst, Hooper & Greenberg 1984): which object, and which of its
// triangles, is nearest at each pixel.

uniform uint u_object_id;  // object index + 1; 0 is left for "nothing"
uniform uint u_prim_base;  // the draw's first triangle within the object's mesh

layout(location = 0) out uint o_object;
layout(location = 1) out uint o_prim;

void main() {
    o_object = u_object_id;
    o_prim = u_prim_base + uint(gl_PrimitiveID);
}
