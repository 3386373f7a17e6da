#version 330 core
// A picked pixel's rays (app/gl/ray_overlay.h) as lines u_width pixels wide: each
// segment is a quad, its corners pushed sideways in screen space. Positions are in view
// space, already cut at the near plane, so every w here is positive.

layout(location = 0) in vec3 a_position;  // this end
layout(location = 1) in vec3 a_other;     // the other end
layout(location = 2) in float a_side;     // -1 or +1: which edge of the quad
layout(location = 3) in vec4 a_colour;

uniform mat4 u_projection;
uniform vec3 u_viewport;  // width, height
uniform float u_width;

out vec4 v_colour;

void main() {
    vec4 p = u_projection * vec4(a_position, 1.0);
    vec4 q = u_projection * vec4(a_other, 1.0);
    vec2 half_size = 0.5 * u_viewport.xy;
    vec2 d = (q.xy / q.w - p.xy / p.w) * half_size;
    float len = length(d);
    vec2 normal = len > 1e-6 ? vec2(-d.y, d.x) / len : vec2(0.0, 1.0);
    p.xy += normal * a_side * 0.5 * u_width / half_size * p.w;
    gl_Position = p;
    v_colour = a_colour;
}
