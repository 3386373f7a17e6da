#version 330 core
// A picked pixel's rays: flat colour, linear; alpha says how much of the view they cover.

in vec4 v_colour;
layout(location = 0) out vec4 o_colour;

void main() { o_colour = v_colour; }
