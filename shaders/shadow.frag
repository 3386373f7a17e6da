#version 330 core
// A shadow map's texel (app/gl/cube_atlas.h): the distance from the light to the
// nearest surface in that direction, linear, so that phong.frag compares distances.

in vec3 v_world;
uniform vec3 u_light;

layout(location = 0) out float o_distance;

void main() { o_distance = length(v_world - u_light); }
