#version 330 core
// The item buffer (Weghorst, Hooper & Greenberg 1984): which object, and which of its
// triangles, is nearest at each pixel.

// Compiled with IDS 1 (object ids alone) or 2 (objects and triangles), as phong.frag.
#ifndef IDS
#define IDS 2
#endif

uniform uint u_object_id;  // object index + 1; 0 is left for "nothing"
layout(location = 0) out uint o_object;
#if IDS > 1
flat in uint v_prim;  // the triangle within the object's mesh (raster.vert)
// > 0: the ids packed into o_object, the object id above this many bits of the triangle
// (app/gl/framebuffer.h, IdLayout; the layout keeps every mesh's triangles below them,
// and a tessellated sphere's or plane's, which nothing reads, are cut to fit)
uniform uint u_prim_bits;
layout(location = 1) out uint o_prim;
#endif

void main() {
#if IDS > 1
    uint prim = v_prim;
    o_object = u_prim_bits == 0u
                   ? u_object_id
                   : (u_object_id << u_prim_bits) | (prim & ((1u << u_prim_bits) - 1u));
    o_prim = prim;
#else
    o_object = u_object_id;
#endif
}
