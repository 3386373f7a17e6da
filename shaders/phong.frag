#version 330 core
// The tracer's local shading, per fragment, with no visible() term (no shadows):
//   I = ka Ia + sum_l (kd max(0, n.l) + ks max(0, r.v)^shininess) I_l
// Same materials, lights, checker and normal rules as core/tracer.cpp and core/scene.cpp.

// Compiled with SHADOW_MAPS, ENV_MAPS and TEXTURES 0 or 1 (app/gl/program.h says why not
// uniforms), and IDS: 0 where the target holds no item buffer, 1 for object ids alone,
// 2 for objects and triangles (RasterRenderer::id_define says why three).

const int kMaxLights = 16;  // RasterRenderer::kMaxLights
#ifndef SHADOW_MAPS
#define SHADOW_MAPS 0
#endif
#ifndef ENV_MAPS
#define ENV_MAPS 0
#endif
#ifndef TEXTURES
#define TEXTURES 0
#endif
#ifndef IDS
#define IDS 0
#endif

in vec3 v_local;
in vec3 v_world;
in vec3 v_object;
in vec3 v_normal;
in vec3 v_face_normal;
in vec2 v_uv;
in vec3 v_colour;

uniform mat3 u_normal_matrix;
uniform mat4 u_shape;
uniform mat4 u_model;
uniform int u_sphere;        // the mesh is the tessellated unit sphere
uniform vec3 u_eye_local;    // the eye in the unit sphere's coordinates

uniform vec3 u_eye;
uniform vec3 u_ambient;
uniform int u_light_count;
uniform int u_light_directional[kMaxLights];
uniform vec3 u_light_vector[kMaxLights];  // position, or the direction the light travels
uniform vec3 u_light_colour[kMaxLights];

// Shadow maps (app/gl/cube_atlas.h): per light a row of six faces in one atlas, each
// texel the distance from the light to the nearest surface.
uniform sampler2D u_shadow_atlas;
uniform int u_shadow_size;  // texels a face side
uniform int u_shadow_rows;  // lights with a row
uniform mat4 u_face_vp[6];  // direction from a cube's centre -> a face's clip space

// Environment maps (app/gl/cube_atlas.h): per mirror or glass object a row of six faces,
// the rest of the scene seen from its centre.
uniform int u_env_terms;  // 1: reflection, 2: refraction, 3: both (the explain map asks for one)
uniform int u_env_row;  // this object's row, or -1
uniform sampler2D u_env_atlas;
uniform int u_env_size;
uniform int u_env_rows;
uniform float u_kr;   // reflectivity
uniform float u_kt;   // transparency
uniform float u_ior;

uniform vec3 u_emission;
// The material's texture multiplies ka and kd as the checker does (core/texture.h: both
// pipelines filter the same linear texels bilinearly at level 0).
uniform int u_textured;
uniform sampler2D u_texture;
uniform vec3 u_ka;
uniform vec3 u_kd;
uniform vec3 u_ks;
uniform float u_shininess;
uniform int u_checker;
uniform vec3 u_checker_a;
uniform vec3 u_checker_b;
uniform float u_checker_scale;
uniform int u_plane;  // a plane's checker lies in the plane
uniform vec3 u_plane_t1;
uniform vec3 u_plane_t2;
uniform vec3 u_pattern_shift;  // Scene::pattern_shift: the scene's origin, folded

layout(location = 0) out vec4 o_colour;  // linear; encoded to sRGB where it is written out
// The item buffer from the same draw (as itembuffer.frag), where the target has room for
// it (Framebuffer::Kind::kColourAndIds, IDS > 0).
#if IDS > 0
uniform uint u_object_id;  // object index + 1
layout(location = 1) out uint o_object;
#endif
#if IDS > 1
flat in uint v_prim;  // the triangle within the object's mesh (raster.vert)
// > 0: the ids packed into o_object, the object id above this many bits of the triangle
// (app/gl/framebuffer.h, IdLayout; the layout keeps every mesh's triangles below them,
// and a tessellated sphere's or plane's, which nothing reads, are cut to fit)
uniform uint u_prim_bits;
layout(location = 2) out uint o_prim;
#endif

struct Surface {
    vec3 world;
    vec3 object;
    vec3 face_normal;
    vec3 normal;
};

// The polygon decides coverage and depth; a sphere's surface point is then taken on
// the true sphere along the pixel's line of sight (the quadratic of the tutorial in the
// unit sphere's space), so its normal is exact and only the silhouette is tessellated.
Surface surface() {
    Surface s = Surface(v_world, v_object, v_face_normal, v_normal);
    if (u_sphere == 0) return s;
    vec3 d = v_local - u_eye_local;
    float a = dot(d, d), b = 2.0 * dot(u_eye_local, d), c = dot(u_eye_local, u_eye_local) - 1.0;
    float discriminant = b * b - 4.0 * a * c;
    vec3 p = normalize(v_local);  // grazing: the nearest point on the sphere
    if (discriminant >= 0.0) {
        float root = sqrt(discriminant);
        float t = c > 0.0 ? (-b - root) / (2.0 * a) : (-b + root) / (2.0 * a);  // entry, or exit from inside
        p = u_eye_local + t * d;
    }
    vec4 object = u_shape * vec4(p, 1.0);
    s.object = object.xyz;
    s.world = (u_model * object).xyz;
    s.face_normal = s.normal = u_normal_matrix * p;
    return s;
}

vec3 pattern(vec3 object) {
    if (u_checker == 0) return vec3(1.0);
    vec3 p = u_plane == 1 ? vec3(dot(object, u_plane_t1), dot(object, u_plane_t2), 0.0) : object;
    p += u_pattern_shift;
    // Each cell's parity as in core/material.h: defined at any coordinate.
    vec3 f = floor(p / u_checker_scale);
    vec3 parity = f - 2.0 * floor(0.5 * f);
    float sum = parity.x + parity.y + parity.z;
    return sum == 0.0 || sum == 2.0 ? u_checker_a : u_checker_b;
}

// Which of a cube's faces a direction from its centre goes through, and where on it (in
// texels from the face's corner).
int cube_face(vec3 d) {
    vec3 a = abs(d);
    return a.x >= a.y && a.x >= a.z ? (d.x > 0.0 ? 0 : 1)
           : a.y >= a.z            ? (d.y > 0.0 ? 2 : 3)
                                   : (d.z > 0.0 ? 4 : 5);
}
vec2 face_texel(int face, vec3 d, float size) {
    vec4 clip = u_face_vp[face] * vec4(d, 1.0);
    return (clip.xy / clip.w * 0.5 + 0.5) * size;
}

// The environment along `d`, as if it were infinitely far (so a near object shows with
// parallax error), filtered between texels of one face.
vec3 environment(vec3 d) {
    int face = cube_face(d);
    float size = float(u_env_size);
    vec2 t = clamp(face_texel(face, d, size), vec2(0.5), vec2(size - 0.5));
    vec2 atlas = vec2(6.0 * size, float(u_env_rows) * size);
    return texture(u_env_atlas, (vec2(face, u_env_row) * size + t) / atlas).rgb;
}

// The share of the 3 x 3 texels around the point's direction that see it (percentage-
// closer filtering). The bias grows with the slope: a texel spans 2 d / size at distance
// d, and more of the surface where the light grazes it.
float shadow_visibility(int light, vec3 world, vec3 n, vec3 to_light) {
    vec3 rel = world - u_light_vector[light];
    int face = cube_face(rel);
    float size = float(u_shadow_size);
    vec2 texel = face_texel(face, rel, size);
    float distance = length(rel);
    float cos_t = clamp(dot(n, to_light), 0.05, 1.0);
    float tan_t = sqrt(1.0 - cos_t * cos_t) / cos_t;
    float bias = 2.0 * distance / size * (1.5 + 2.0 * min(tan_t, 10.0));
    vec2 atlas = vec2(6.0 * size, float(u_shadow_rows) * size);
    float lit = 0.0;
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            vec2 t = clamp(floor(texel) + vec2(dx, dy) + 0.5, vec2(0.5), vec2(size - 0.5));
            float stored = texture(u_shadow_atlas, (vec2(face, light) * size + t) / atlas).r;
            lit += distance - bias <= stored ? 1.0 : 0.0;
        }
    }
    return lit / 9.0;
}

void main() {
#if IDS == 1
    o_object = u_object_id;
#elif IDS > 1
    uint prim = v_prim;
    o_object = u_prim_bits == 0u
                   ? u_object_id
                   : (u_object_id << u_prim_bits) | (prim & ((1u << u_prim_bits) - 1u));
    o_prim = prim;
#endif
    Surface s = surface();
    vec3 to_viewer = normalize(u_eye - s.world);
    // Normals face the viewer; an interpolated normal leaning past the silhouette gives
    // way to the geometric one.
    vec3 ng = normalize(s.face_normal);
    vec3 ns = normalize(s.normal);
    bool front = dot(ng, to_viewer) > 0.0;
    ng = front ? ng : -ng;
    ns = front ? ns : -ns;
    vec3 n = dot(ns, ng) > 0.0 ? ns : ng;

    vec3 c = pattern(s.object) * v_colour;
#if TEXTURES == 1
    if (u_textured == 1) c *= texture(u_texture, v_uv).rgb;
#endif
    vec3 colour = u_emission + u_ka * c * u_ambient;
    for (int i = 0; i < u_light_count; ++i) {
        vec3 to_light = u_light_directional[i] == 1 ? -u_light_vector[i] : u_light_vector[i] - s.world;
        float distance = length(to_light);
        if (!(distance > 0.0)) continue;  // a light on the surface lights nothing there (core/tracer.cpp)
        to_light /= distance;
        float n_dot_l = dot(n, to_light);
        if (n_dot_l <= 0.0) continue;
#if SHADOW_MAPS == 1
        float visible = i < u_shadow_rows && u_light_directional[i] == 0
                            ? shadow_visibility(i, s.world, n, to_light)
                            : 1.0;
#else
        float visible = 1.0;  // the classic pipeline: no shadows
#endif
        if (visible <= 0.0) continue;
        float r_dot_v = max(0.0, dot(reflect(-to_light, n), to_viewer));
        vec3 specular = r_dot_v > 0.0 ? u_ks * pow(r_dot_v, u_shininess) : vec3(0.0);
        colour += visible * (u_kd * c * n_dot_l + specular) * u_light_colour[i];
    }
#if ENV_MAPS == 1
    if (u_env_row >= 0) {
        // The tracer's R = local + kr R_reflected + kt R_refracted, with the rays' colours
        // looked up instead of traced; the refraction bends once, at this surface.
        vec3 incoming = -to_viewer;
        if (u_kr > 0.0 && (u_env_terms & 1) != 0) colour += u_kr * environment(reflect(incoming, n));
        if (u_kt > 0.0 && (u_env_terms & 2) != 0) {
            vec3 t = refract(incoming, n, 1.0 / u_ior);
            colour += u_kt * environment(dot(t, t) > 0.0 ? t : reflect(incoming, n));
        }
    }
#endif
    o_colour = vec4(colour, 1.0);
}
