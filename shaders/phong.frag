#version 330 core
// The tracer's local shading, per fragment, with no visible() term (no shadows):
//   I = ka Ia + sum_l (kd max(0, n.l) + ks max(0, r.v)^shininess) I_l
// Same materials, lights, checker and normal rules as core/tracer.cpp and core/scene.cpp.

const int kMaxLights = 16;  // RasterRenderer::kMaxLights

in vec3 v_local;
in vec3 v_world;
in vec3 v_object;
in vec3 v_normal;
in vec3 v_face_normal;

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

void main() {
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

    vec3 c = pattern(s.object);
    vec3 colour = u_ka * c * u_ambient;
    for (int i = 0; i < u_light_count; ++i) {
        vec3 to_light = u_light_directional[i] == 1 ? -u_light_vector[i] : u_light_vector[i] - s.world;
        float distance = length(to_light);
        if (!(distance > 0.0)) continue;  // a light on the surface lights nothing there (core/tracer.cpp)
        to_light /= distance;
        float n_dot_l = dot(n, to_light);
        if (n_dot_l <= 0.0) continue;
        float r_dot_v = max(0.0, dot(reflect(-to_light, n), to_viewer));
        vec3 specular = r_dot_v > 0.0 ? u_ks * pow(r_dot_v, u_shininess) : vec3(0.0);
        colour += (u_kd * c * n_dot_l + specular) * u_light_colour[i];
    }
    o_colour = vec4(colour, 1.0);
}
