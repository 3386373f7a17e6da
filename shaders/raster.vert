#version 330 core
// Shared by the colour pass (phong.frag) and the item-buffer pass (itembuffer.frag).
// Positions go mesh -> object space (u_shape: a sphere's centre and radius, a plane's
// frame) -> world (u_model: the object's transform) -> clip (core's Camera matrices).

layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;       // shading normal
layout(location = 2) in vec3 a_face_normal;  // geometric normal
layout(location = 3) in vec2 a_uv;           // texture coordinates (core/texture.h)
layout(location = 4) in vec3 a_colour;       // vertex colour (white where a mesh has none)

uniform mat4 u_shape;
uniform mat4 u_model;
uniform mat3 u_normal_matrix;  // inverse transpose of mat3(u_model * u_shape)
uniform mat4 u_view_projection;

out vec3 v_local;   // the mesh's own coordinates (on a unit sphere: the normal)
out vec3 v_world;
out vec3 v_object;  // where the checker is evaluated, as in the tracer
out vec3 v_normal;
out vec3 v_face_normal;  // the same at all three corners of a mesh triangle
out vec2 v_uv;
out vec3 v_colour;
#if defined(IDS) && IDS > 1
// The triangle's index within its mesh, for the item buffer (phong.frag, itembuffer.frag):
// a mesh is drawn as arrays of triangles, its own from vertex 0 (GpuScene::add_mesh_draws,
// which starts a draw of triangles from `start` at vertex 3 * start). A flat output, not
// gl_PrimitiveID in the fragment shader, which costs llvmpipe a pass over the primitives
// (docs/BENCHMARKS.md, "thirty-second session").
flat out uint v_prim;
#endif

void main() {
    vec4 object = u_shape * vec4(a_position, 1.0);
    vec4 world = u_model * object;
    v_local = a_position;
    v_object = object.xyz;
    v_world = world.xyz;
    v_normal = u_normal_matrix * a_normal;
    v_face_normal = u_normal_matrix * a_face_normal;
    v_uv = a_uv;
    v_colour = a_colour;
#if defined(IDS) && IDS > 1
    v_prim = uint(gl_VertexID) / 3u;
#endif
    gl_Position = u_view_projection * world;
}
