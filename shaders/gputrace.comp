#version 430 core
// The Whitted tracer of core/tracer.cpp on the GPU, one invocation per pixel: the same
// intersection tests (the tutorial's sphere, plane and triangle, the watertight test for
// mesh triangles), the same ray offsets, Phong with shadow feelers, reflection and
// refraction with the media a ray is inside. No recursion in GLSL: the rays still to
// trace wait on a stack, each with the weight it adds to the pixel. Buffer layouts:
// core/flat_scene.h and docs/gpu-tracer.md. STACK (rays waiting) is set by the host
// from the maximum depth. With RAY_QUERIES 1 it answers a list of rays instead of
// tracing pixels (rtbench --gpu): each ray's closest hit, or whether anything blocks it.
#ifndef RAY_QUERIES
#define RAY_QUERIES 0
#endif
layout(local_size_x = 8, local_size_y = 8) in;

struct Node { vec3 lo; uint first; vec3 hi; uint count; };
struct Object {
    mat4 to_object; mat4 to_world; mat4 normal_matrix;
    vec4 shape[3]; vec4 pattern_hi; vec4 pattern_lo;
    uint kind; uint material; uint mesh; uint flags;
};
struct Mesh { uint root, triangles, normals, uvs, colours, materials, pad0, pad1; };
struct Material {
    vec4 ka_shininess; vec4 kd_reflectivity; vec4 ks_transparency; vec4 emission_ior;
    vec4 checker_a_scale; vec4 checker_b; ivec4 texture;
};

layout(std430, binding = 0) readonly buffer Nodes { Node nodes[]; };
layout(std430, binding = 1) readonly buffer Words { uint words[]; };  // orders, ids, textures
layout(std430, binding = 2) readonly buffer Rows { vec4 rows[]; };    // vertices ... lights
layout(std430, binding = 3) readonly buffer Objects { Object objects[]; };
layout(std430, binding = 4) readonly buffer Meshes { Mesh meshes[]; };
layout(std430, binding = 5) readonly buffer Materials { Material materials[]; };
layout(std430, binding = 6) writeonly buffer Pixels { vec4 pixels[]; };  // or ray answers
#if RAY_QUERIES
// Two rows a ray: (origin, t_max), (direction, 1 for any hit); answers (t, triangle, object).
layout(std430, binding = 7) readonly buffer Queries { vec4 queries[]; };
uniform uint query_count;
#endif

// Where each array starts in words[] and rows[] (gpu_tracer.cpp).
uniform uint object_order_at, triangle_order_at, unbounded_at, unbounded_count,
    triangle_materials_at, textures_at;
uniform bool has_tree;  // some object is bounded
uniform uint vertices_at, normals_at, uvs_at, colours_at, texels_at, lights_at, light_count;
uniform vec3 eye, cam_u, cam_v, cam_n;
uniform float cam_w, cam_h, cam_dist;
uniform ivec2 size;
uniform vec3 background, ambient;
uniform bool shadows, reflections, refractions;
uniform int max_depth;
uniform float min_weight;

const float kInf = uintBitsToFloat(0x7f800000u);
const uint kNone = 0xffffffffu;
const uint kSphere = 0u, kPlane = 1u, kTriangle = 2u, kMesh = 3u;
const uint kTransformed = 1u, kOwnMaterials = 2u;
const int kMedia = 8;  // core/medium.h's capacity

struct Ray { vec3 o; vec3 d; };
struct Hit { float t; uint object; uint prim; float b1; float b2; };

// --- intersection tests (core/shapes.cpp, core/triangle4.h, core/aabb.h) -------------
bool finite_ray(Ray r) { return !any(isnan(r.o)) && !any(isinf(r.o)) && !any(isnan(r.d)) && !any(isinf(r.d)); }

float slab_entry(vec3 lo, vec3 hi, Ray r, vec3 inv_dir, float t_max) {
    float enter = 0.0, leave = t_max;
    for (int a = 0; a < 3; ++a) {
        float t_lo = (lo[a] - r.o[a]) * inv_dir[a], t_hi = (hi[a] - r.o[a]) * inv_dir[a];
        bool negative = inv_dir[a] < 0.0;
        enter = max(enter, negative ? t_hi : t_lo);
        leave = min(leave, negative ? t_lo : t_hi);
    }
    return enter <= leave * 1.00000024 ? enter : kInf;
}

bool sphere_t(vec4 s, Ray r, float t_max, out float t) {
    vec3 f = r.o - s.xyz;
    float A = dot(r.d, r.d), f_dot_d = dot(f, r.d), B = 2.0 * f_dot_d;
    float C = dot(f, f) - s.w * s.w;
    vec3 closest = f - (f_dot_d / A) * r.d;
    float disc = 4.0 * A * (s.w * s.w - dot(closest, closest));
    t = kInf;
    if (!(disc > 0.0)) return false;
    float q = -0.5 * (B + (B < 0.0 ? -sqrt(disc) : sqrt(disc)));
    float ta = q / A, tb = q != 0.0 ? C / q : -ta;
    float t1 = min(ta, tb), t2 = max(ta, tb);
    if (t1 > 0.0 && t1 < t_max) t = t1;
    else if (t2 > 0.0 && t2 < t_max) t = t2;
    return t < kInf;
}

bool plane_t(vec4 p, Ray r, float t_max, out float t) {
    float d_dot_n = dot(r.d, p.xyz);
    t = d_dot_n == 0.0 ? kInf : (p.w - dot(r.o, p.xyz)) / d_dot_n;
    return t > 0.0 && t < t_max;
}

// The tutorial's triangle (a Triangle object): the plane hit, then three edge tests.
bool triangle_t(vec3 a, vec3 b, vec3 c, Ray r, inout Hit h) {
    vec3 n = cross(b - a, c - a);
    float d_dot_n = dot(r.d, n);
    if (d_dot_n == 0.0) return false;
    float t = dot(a - r.o, n) / d_dot_n;
    if (!(t > 0.0 && t < h.t)) return false;
    vec3 p = r.o + t * r.d;
    float ab = dot(cross(b - a, p - a), n), bc = dot(cross(c - b, p - b), n),
          ca = dot(cross(a - c, p - c), n);
    if (ab < 0.0 || bc < 0.0 || ca < 0.0) return false;
    float inv_nn = 1.0 / dot(n, n);
    h.t = t; h.prim = 0u; h.b1 = ca * inv_nn; h.b2 = ab * inv_nn;
    return true;
}

// The watertight test (Woop, Benthin and Wald), with its rounding bound on t.
struct Sheared { ivec3 k; vec3 s; vec3 o; };
Sheared shear(Ray r) {
    vec3 a = abs(r.d);
    int kz = a.x > a.y ? (a.x > a.z ? 0 : 2) : (a.y > a.z ? 1 : 2);
    int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
    if (r.d[kz] < 0.0) { int k = kx; kx = ky; ky = k; }
    return Sheared(ivec3(kx, ky, kz), vec3(r.d[kx] / r.d[kz], r.d[ky] / r.d[kz], 1.0 / r.d[kz]), r.o);
}
float gamma_n(float n) { return n * 5.9604644775390625e-8 / (1.0 - n * 5.9604644775390625e-8); }
bool watertight(vec3 va, vec3 vb, vec3 vc, Sheared r, float t_max, out float t, out float b1, out float b2) {
    vec3 A = va - r.o, B = vb - r.o, C = vc - r.o;
    float az = A[r.k.z], bz = B[r.k.z], cz = C[r.k.z];
    float ax = A[r.k.x] - r.s.x * az, ay = A[r.k.y] - r.s.y * az;
    float bx = B[r.k.x] - r.s.x * bz, by = B[r.k.y] - r.s.y * bz;
    float cx = C[r.k.x] - r.s.x * cz, cy = C[r.k.y] - r.s.y * cz;
    float u = cx * by - cy * bx, v = ax * cy - ay * cx, w = bx * ay - by * ax;
    bool same = (u >= 0.0 && v >= 0.0 && w >= 0.0) || (u <= 0.0 && v <= 0.0 && w <= 0.0);
    float det = u + v + w;
    if (!same || det == 0.0) return false;
    float t_scaled = r.s.z * (u * az + v * bz + w * cz);
    t = t_scaled / det;
    if (!(t > 0.0 && t < t_max)) return false;
    float x_max = max(max(abs(ax), abs(bx)), abs(cx)), y_max = max(max(abs(ay), abs(by)), abs(cy));
    float z_max = max(max(abs(az), abs(bz)), abs(cz)) * abs(r.s.z);
    float dx = gamma_n(5.0) * (x_max + z_max), dy = gamma_n(5.0) * (y_max + z_max);
    float de = 2.0 * (gamma_n(2.0) * x_max * y_max + dy * x_max + dx * y_max);
    float e_max = max(max(abs(u), abs(v)), abs(w));
    float dt = 3.0 * (gamma_n(3.0) * e_max * z_max + de * z_max + gamma_n(3.0) * z_max * e_max);
    if (!(abs(t_scaled) > dt)) return false;
    b1 = v / det; b2 = w / det;
    return true;
}

// A mesh's tree, near child first; with any_hit the first hit ends the walk.
bool intersect_mesh(uint mesh_index, Ray r, bool any_hit, inout Hit h) {
    uint root = meshes[mesh_index].root, first_triangle = meshes[mesh_index].triangles;
    if (!finite_ray(r)) return false;
    vec3 inv_dir = 1.0 / r.d;
    if (slab_entry(nodes[root].lo, nodes[root].hi, r, inv_dir, h.t) == kInf) return false;
    Sheared s = shear(r);
    uint stack[64]; float entry[64];
    int top = 0;
    uint index = root;
    bool found = false;
    for (;;) {
        Node node = nodes[index];
        if (node.count != 0u) {
            for (uint slot = node.first; slot < node.first + node.count; ++slot) {
                uint tri = words[triangle_order_at + slot], at = vertices_at + 3u * (first_triangle + tri);
                float t, b1, b2;
                if (watertight(rows[at].xyz, rows[at + 1u].xyz, rows[at + 2u].xyz, s, h.t, t, b1, b2)) {
                    h.t = t; h.prim = tri; h.b1 = b1; h.b2 = b2;
                    found = true;
                    if (any_hit) return true;
                }
            }
        } else {
            uint left = index + 1u, right = node.first;
            float tl = slab_entry(nodes[left].lo, nodes[left].hi, r, inv_dir, h.t);
            float tr = slab_entry(nodes[right].lo, nodes[right].hi, r, inv_dir, h.t);
            if (tl != kInf && tr != kInf) {
                bool left_first = tl <= tr;
                stack[top] = left_first ? right : left; entry[top] = left_first ? tr : tl; ++top;
                index = left_first ? left : right;
                continue;
            }
            if (tl != kInf || tr != kInf) { index = tl != kInf ? left : right; continue; }
        }
        while (top > 0 && entry[top - 1] >= h.t) --top;
        if (top == 0) break;
        index = stack[--top];
    }
    return found;
}

// The ray in object i's space (fields read one by one: a whole Object is 288 bytes).
Ray object_ray(uint i, Ray r) {
    if ((objects[i].flags & kTransformed) == 0u) return r;
    mat4 m = objects[i].to_object;
    return Ray((m * vec4(r.o, 1.0)).xyz, (m * vec4(r.d, 0.0)).xyz);
}

// One object: on a hit, h is replaced (t, triangle, barycentrics) and true returned.
bool intersect_object(uint i, Ray world, bool any_hit, inout Hit h) {
    Ray r = object_ray(i, world);
    uint kind = objects[i].kind;
    float t;
    bool hit = false;
    if (kind == kSphere) hit = sphere_t(objects[i].shape[0], r, h.t, t);
    else if (kind == kPlane) hit = plane_t(objects[i].shape[0], r, h.t, t);
    else if (kind == kTriangle) hit = triangle_t(objects[i].shape[0].xyz, objects[i].shape[1].xyz, objects[i].shape[2].xyz, r, h);
    else hit = intersect_mesh(objects[i].mesh, r, any_hit, h);
    if (hit && kind <= kPlane) h = Hit(t, i, 0u, 0.0, 0.0);  // nothing of a mesh hit stays
    if (hit) h.object = i;
    return hit;
}

// The closest hit in (0, h.t), or with any_hit whether there is one (shadow feelers).
bool intersect_scene(Ray r, bool any_hit, inout Hit h) {
    bool found = false;
    for (uint k = 0u; k < unbounded_count; ++k) {
        found = intersect_object(words[unbounded_at + k], r, any_hit, h) || found;
        if (found && any_hit) return true;
    }
    if (!has_tree || !finite_ray(r)) return found;
    vec3 inv_dir = 1.0 / r.d;
    if (slab_entry(nodes[0].lo, nodes[0].hi, r, inv_dir, h.t) == kInf) return found;
    uint stack[64]; float entry[64];
    int top = 0;
    uint index = 0u;
    for (;;) {
        Node node = nodes[index];
        if (node.count != 0u) {
            for (uint slot = node.first; slot < node.first + node.count; ++slot) {
                if (intersect_object(words[object_order_at + slot], r, any_hit, h)) {
                    found = true;
                    if (any_hit) return true;
                }
            }
        } else {
            uint left = index + 1u, right = node.first;
            float tl = slab_entry(nodes[left].lo, nodes[left].hi, r, inv_dir, h.t);
            float tr = slab_entry(nodes[right].lo, nodes[right].hi, r, inv_dir, h.t);
            if (tl != kInf && tr != kInf) {
                bool left_first = tl <= tr;
                stack[top] = left_first ? right : left; entry[top] = left_first ? tr : tl; ++top;
                index = left_first ? left : right;
                continue;
            }
            if (tl != kInf || tr != kInf) { index = tl != kInf ? left : right; continue; }
        }
        while (top > 0 && entry[top - 1] >= h.t) --top;
        if (top == 0) break;
        index = stack[--top];
    }
    return found;
}

bool occluded(Ray r, float t_max) {
    Hit h = Hit(t_max, kNone, 0u, 0.0, 0.0);
    return intersect_scene(r, true, h);
}

// --- the surface at a hit (Scene::surface) -----------------------------------------
struct Surface { vec3 p; vec3 ng; vec3 n; uint material; vec3 pattern; vec2 uv; vec3 colour; };

void tangent_frame(vec3 n, out vec3 t1, out vec3 t2) {
    vec3 m = vec3(n.x, n.z, n.y);
    float sgn = m.z < 0.0 ? -1.0 : 1.0;
    float a = -1.0 / (sgn + m.z), b = m.x * m.y * a;
    vec3 s1 = vec3(1.0 + sgn * m.x * m.x * a, sgn * b, -sgn * m.x);
    vec3 s2 = vec3(b, sgn + m.y * m.y * a, -m.y);
    t1 = vec3(s1.x, s1.z, s1.y); t2 = vec3(s2.x, s2.z, s2.y);
}

vec3 corners(uint at, float b1, float b2) {
    return (1.0 - b1 - b2) * rows[at].xyz + b1 * rows[at + 1u].xyz + b2 * rows[at + 2u].xyz;
}

// x mod period as x - period k, k = floor(x / period), with period k taken exactly: as
// the sum of two floats (Dekker's product: both factors have 24 bits, so the 48 of the
// product fit two floats), x - (that) exact by Sterbenz's lemma, one rounding at the end.
// Rounding period k to one float first (what mod() does) moved the squares of a small
// checker far out (x = 1000, period 0.002) by 0.45 % of a square against the CPU's, which
// folds in double. `precise` keeps the compiler from fusing or reordering any of it (and
// fma() is not fused on every driver: llvmpipe splits it). k may be one off (x / period
// is rounded): the last step folds that back.
vec3 exact_mod(vec3 x, float period) {
    vec3 k = floor(x / period);
    precise vec3 product = period * k;
    precise float pc = 4097.0 * period;  // Veltkamp's split, 2^12 + 1
    precise vec3 kc = 4097.0 * k;
    precise float ph = pc - (pc - period), pl = period - ph;
    precise vec3 kh = kc - (kc - k), kl = k - kh;
    precise vec3 error = ((ph * kh - product) + ph * kl + pl * kh) + pl * kl;
    precise vec3 r = (x - product) - error;
    return r - period * floor(r / period);
}

Surface surface(Ray world, Hit h) {
    uint oi = h.object;  // its fields read one by one
    Ray r = object_ray(h.object, world);
    Surface s = Surface(vec3(0.0), vec3(0.0), vec3(0.0), objects[oi].material, vec3(0.0), vec2(0.0), vec3(1.0));
    if (objects[oi].kind == kSphere) {
        vec3 n = normalize(r.o + h.t * r.d - objects[oi].shape[0].xyz);
        s.p = objects[oi].shape[0].xyz + objects[oi].shape[0].w * n; s.ng = s.n = n; s.pattern = s.p;
    } else if (objects[oi].kind == kPlane) {
        vec3 n = objects[oi].shape[0].xyz, p = r.o + h.t * r.d, t1, t2;
        p -= (dot(p, n) - objects[oi].shape[0].w) * n;
        s.p = p; s.ng = s.n = n;
        tangent_frame(n, t1, t2);
        s.pattern = vec3(dot(p, t1), dot(p, t2), 0.0);
    } else if (objects[oi].kind == kTriangle) {
        vec3 a = objects[oi].shape[0].xyz, b = objects[oi].shape[1].xyz, c = objects[oi].shape[2].xyz;
        s.p = (1.0 - h.b1 - h.b2) * a + h.b1 * b + h.b2 * c; s.ng = s.n = cross(b - a, c - a);
        s.pattern = s.p;
    } else {
        Mesh m = meshes[objects[oi].mesh];
        uint tri = m.triangles + h.prim, at = vertices_at + 3u * tri;
        s.p = corners(at, h.b1, h.b2);
        s.ng = cross(rows[at + 1u].xyz - rows[at].xyz, rows[at + 2u].xyz - rows[at].xyz);
        s.n = m.normals == kNone ? s.ng : corners(normals_at + 3u * (m.normals + h.prim), h.b1, h.b2);
        if (m.uvs != kNone) {
            uint u = uvs_at + 2u * (m.uvs + h.prim);
            s.uv = (1.0 - h.b1 - h.b2) * rows[u].xy + h.b1 * rows[u].zw + h.b2 * rows[u + 1u].xy;
        }
        if (m.colours != kNone) s.colour = corners(colours_at + 3u * (m.colours + h.prim), h.b1, h.b2);
        if ((objects[oi].flags & kOwnMaterials) != 0u && m.materials != kNone)
            s.material = words[triangle_materials_at + m.materials + h.prim];
        s.pattern = s.p;
    }
    float scale = materials[s.material].checker_a_scale.w;
    if ((objects[oi].flags & kTransformed) == 0u && scale > 0.0) {  // Checker::shift of the origin
        float period = 2.0 * scale;
        s.pattern += exact_mod(exact_mod(objects[oi].pattern_hi.xyz, period) +
                               exact_mod(objects[oi].pattern_lo.xyz, period), period);
    }
    if ((objects[oi].flags & kTransformed) != 0u) {
        s.p = (objects[oi].to_world * vec4(s.p, 1.0)).xyz;
        s.ng = normalize(mat3(objects[oi].normal_matrix) * s.ng);
        s.n = normalize(mat3(objects[oi].normal_matrix) * s.n);
    } else {
        s.ng = normalize(s.ng); s.n = normalize(s.n);
    }
    bool front = dot(world.d, s.ng) < 0.0;
    s.ng = front ? s.ng : -s.ng;
    vec3 n = front ? s.n : -s.n;
    s.n = dot(n, s.ng) > 0.0 ? n : s.ng;
    return s;
}

// --- shading (Tracer::phong) ---------------------------------------------------------
vec3 offset_ray_origin(vec3 p, vec3 n) {
    vec3 out_p;
    for (int i = 0; i < 3; ++i) {
        int ulps = int(256.0 * n[i]);
        float stepped = intBitsToFloat(floatBitsToInt(p[i]) + (p[i] < 0.0 ? -ulps : ulps));
        out_p[i] = abs(p[i]) < 1.0 / 32.0 ? p[i] + n[i] / 65536.0 : stepped;
    }
    return out_p;
}

vec3 checker(Material m, vec3 p) {
    float scale = m.checker_a_scale.w;
    vec3 f = floor(p / scale);
    vec3 parity = f - 2.0 * floor(0.5 * f);
    float sum = parity.x + parity.y + parity.z;
    return sum == 0.0 || sum == 2.0 ? m.checker_a_scale.xyz : m.checker_b.xyz;
}

int wrap_texel(int i, int n, int mode) {
    if (mode == 1) return clamp(i, 0, n - 1);
    int period = mode == 2 ? 2 * n : n;
    int m = i - period * int(floor(float(i) / float(period)));
    return mode == 2 && m >= n ? period - 1 - m : m;
}

float fold(float c, int mode) {
    if (isinf(c) || isnan(c)) return 0.0;
    if (mode == 1) return c;
    float period = mode == 2 ? 2.0 : 1.0;
    return c - period * floor(c / period);
}

vec3 sample_texture(ivec4 tex, vec2 uv) {
    uint at = textures_at + 4u * uint(tex.x);
    int first = int(words[at]), w = int(words[at + 1u]), h = int(words[at + 2u]);
    if (w <= 0 || h <= 0) return vec3(1.0);
    float x = fold(uv.x, tex.y) * float(w) - 0.5, y = fold(uv.y, tex.z) * float(h) - 0.5;
    float fx = floor(x), fy = floor(y), ax = x - fx, ay = y - fy;
    int x0 = int(clamp(fx, -2.0 * float(w), 2.0 * float(w)));
    int y0 = int(clamp(fy, -2.0 * float(h), 2.0 * float(h)));
    int xa = wrap_texel(x0, w, tex.y), xb = wrap_texel(x0 + 1, w, tex.y);
    int ya = wrap_texel(y0, h, tex.z), yb = wrap_texel(y0 + 1, h, tex.z);
    uint base = texels_at + uint(first);
    vec3 top = (1.0 - ax) * rows[base + uint(ya * w + xa)].xyz + ax * rows[base + uint(ya * w + xb)].xyz;
    vec3 bottom = (1.0 - ax) * rows[base + uint(yb * w + xa)].xyz + ax * rows[base + uint(yb * w + xb)].xyz;
    return (1.0 - ay) * top + ay * bottom;
}

// The shadow feeler's direction from p and its t limit (Light::feeler).
float feeler(uint light, vec3 p, out vec3 dir) {
    vec4 position_type = rows[lights_at + 3u * light];
    if (position_type.w == 0.0) { dir = position_type.xyz - p; return 1.0; }
    dir = -rows[lights_at + 3u * light + 1u].xyz;
    return kInf;
}

bool visible(vec3 p, Surface s, uint light) {
    vec3 dir;
    float t_max = feeler(light, p, dir);
    if (dot(dir, s.ng) <= 0.0) {
        vec3 from_surface;
        feeler(light, s.p, from_surface);
        return dot(from_surface, s.ng) > 0.0;
    }
    return !occluded(Ray(p, dir), t_max);
}

vec3 phong(Ray r, Surface s, Material m) {
    vec3 pattern = m.checker_a_scale.w > 0.0 ? checker(m, s.pattern) : vec3(1.0);
    if (m.texture.x >= 0) pattern *= sample_texture(m.texture, s.uv);
    pattern *= s.colour;
    vec3 colour = m.emission_ior.xyz + m.ka_shininess.xyz * pattern * ambient;
    vec3 to_viewer = -normalize(r.d), p = offset_ray_origin(s.p, s.ng);
    for (uint l = 0u; l < light_count; ++l) {
        vec3 to_light;
        feeler(l, s.p, to_light);
        float distance = length(to_light);
        if (!(distance > 0.0) || isinf(distance)) continue;
        to_light /= distance;
        float n_dot_l = dot(s.n, to_light);
        if (n_dot_l <= 0.0) continue;
        if (shadows && !visible(p, s, l)) continue;
        vec3 mirrored = -to_light - 2.0 * dot(-to_light, s.n) * s.n;
        float r_dot_v = max(0.0, dot(mirrored, to_viewer));
        vec3 specular = r_dot_v > 0.0 ? m.ks_transparency.xyz * pow(r_dot_v, m.ka_shininess.w) : vec3(0.0);
        colour += (m.kd_reflectivity.xyz * pattern * n_dot_l + specular) * rows[lights_at + 3u * l + 2u].xyz;
    }
    return colour;
}

// --- the rays still to trace (Tracer::shade_parts, reflected, refracted) ------------
struct Pending {
    Ray ray; float weight; int depth;
    uint media_object[kMedia]; float media_ior[kMedia]; int media_size;
};
Pending stack[STACK];  // refracted rays waiting while their reflected sibling is traced
int stack_top = 0;

void push(Pending p) { if (stack_top < STACK) stack[stack_top++] = p; }

// Crossing a surface of `object` (MediumStack::cross): updates p's media, returns the
// indices on both sides.
vec2 cross_medium(inout Pending p, uint object, float object_ior) {
    float eta_from = p.media_size == 0 ? 1.0 : p.media_ior[p.media_size - 1];
    int at = -1;
    for (int i = p.media_size - 1; i >= 0 && at < 0; --i)
        if (p.media_object[i] == object) at = i;
    if (at < 0) {  // entering
        if (p.media_size == kMedia) {
            for (int i = 0; i + 1 < kMedia; ++i) { p.media_object[i] = p.media_object[i + 1]; p.media_ior[i] = p.media_ior[i + 1]; }
            --p.media_size;
        }
        p.media_object[p.media_size] = object; p.media_ior[p.media_size] = object_ior; ++p.media_size;
        return vec2(eta_from, object_ior);
    }
    if (at == p.media_size - 1) {  // leaving the innermost
        --p.media_size;
        return vec2(eta_from, p.media_size == 0 ? 1.0 : p.media_ior[p.media_size - 1]);
    }
    for (int i = at; i + 1 < p.media_size; ++i) { p.media_object[i] = p.media_object[i + 1]; p.media_ior[i] = p.media_ior[i + 1]; }
    --p.media_size;
    return vec2(eta_from, eta_from);  // overlapping glass: straight on
}

// Depth first, the ray being traced kept out of the stack: a hit carries on with its
// reflected ray (or its refracted one where there is no reflection) and pushes the
// refracted ray only when it has both.
vec3 trace_pixel(Ray primary) {
    Pending e;
    e.ray = primary; e.weight = 1.0; e.depth = 0; e.media_size = 0;
    vec3 colour = vec3(0.0);
    for (;;) {
        Hit h = Hit(kInf, kNone, 0u, 0.0, 0.0);
        if (!intersect_scene(e.ray, false, h)) {
            colour += e.weight * background;
        } else {
            Surface s = surface(e.ray, h);
            Material m = materials[s.material];
            colour += e.weight * phong(e.ray, s, m);
            float reflectivity = m.kd_reflectivity.w, transparency = m.ks_transparency.w;
            bool reflect = e.depth < max_depth && reflections && reflectivity * e.weight >= min_weight;
            bool refract = e.depth < max_depth && refractions && transparency * e.weight >= min_weight;
            vec3 d = normalize(e.ray.d);
            vec3 mirror_dir = d - 2.0 * dot(d, s.n) * s.n;
            if (refract) {
                Pending next = e;
                next.weight = e.weight * transparency; next.depth = e.depth + 1;
                vec2 eta = cross_medium(next, h.object, m.emission_ior.w);
                float ratio = eta.x / eta.y, cos_i = -dot(d, s.n);
                float sin2_t = ratio * ratio * max(0.0, 1.0 - cos_i * cos_i);
                if (sin2_t > 1.0) {  // total internal reflection: the media stay as they were
                    next.media_size = e.media_size;
                    next.media_object = e.media_object; next.media_ior = e.media_ior;
                    next.ray = Ray(offset_ray_origin(s.p, s.ng), mirror_dir);
                } else {
                    next.ray = Ray(offset_ray_origin(s.p, -s.ng), ratio * d + (ratio * cos_i - sqrt(1.0 - sin2_t)) * s.n);
                }
                if (!reflect) { e = next; continue; }
                push(next);
            }
            if (reflect) {
                e.ray = Ray(offset_ray_origin(s.p, s.ng), mirror_dir);
                e.weight *= reflectivity; e.depth += 1;
                continue;
            }
        }
        if (stack_top == 0) break;
        e = stack[--stack_top];
    }
    return colour;
}

#if RAY_QUERIES
void main() {
    uint i = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * 64u + gl_LocalInvocationIndex;
    if (i >= query_count) return;
    vec4 a = queries[2u * i], b = queries[2u * i + 1u];
    Hit h = Hit(a.w, kNone, 0u, 0.0, 0.0);
    bool hit = intersect_scene(Ray(a.xyz, b.xyz), b.w != 0.0, h);
    pixels[i] = hit ? vec4(b.w != 0.0 ? 0.0 : h.t, uintBitsToFloat(h.prim), uintBitsToFloat(h.object), 1.0)
                    : vec4(kInf, uintBitsToFloat(kNone), uintBitsToFloat(kNone), 0.0);
}
#else
void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (pixel.x >= size.x || pixel.y >= size.y) return;
    float sx = cam_w * (2.0 * (float(pixel.x) + 0.5) / float(size.x) - 1.0);
    float sy = cam_h * (2.0 * (float(pixel.y) + 0.5) / float(size.y) - 1.0);
    Ray r = Ray(eye, -cam_dist * cam_n + sx * cam_u + sy * cam_v);
    pixels[pixel.y * size.x + pixel.x] = vec4(trace_pixel(r), 1.0);
}
#endif
