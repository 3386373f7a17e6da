#version 330 core
// The viewer's views (app/gl/compositor.h). Images are linear; the output is sRGB
// encoded with core's transfer function, so the screen shows what the PNG files hold.
// Compiled once per view (VIEW: 0 raster, 1 traced, 2 split, 3 difference, 4 item buffer,
// 5 why), DIFF_MODE (0 heat, 1 signed, 2 per channel: app/gl/compositor.h) and OVERLAY
// (0, 1): llvmpipe would otherwise run every view's texture reads for every pixel.
#ifndef VIEW
#define VIEW 2
#endif
#ifndef DIFF_MODE
#define DIFF_MODE 0
#endif
#ifndef OVERLAY
#define OVERLAY 0
#endif

uniform sampler2D u_raster;
uniform sampler2D u_traced;
uniform usampler2D u_ids;
uniform uint u_ids_shift;     // the ids' packed triangle bits (0: object ids alone)
uniform sampler2D u_heat;     // core's heat_colour(t), 256 texels
uniform sampler2D u_palette;  // core's item_colour(id), one texel per id
uniform sampler2D u_explain;  // core's explain_colours: each pixel its cause's colour
uniform sampler2D u_overlay;  // a picked pixel's rays, alpha 0 elsewhere
uniform int u_palette_size;
uniform vec3 u_viewport;      // width, height
uniform float u_divider;
uniform int u_swap;
uniform float u_diff_scale;
uniform float u_diff_threshold;  // > 0: show a mask of the pixels over it instead

out vec4 o_colour;

vec3 srgb_encode(vec3 linear) {
    vec3 c = clamp(linear, 0.0, 1.0);
    return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}

void main() {
    vec2 uv = gl_FragCoord.xy / u_viewport.xy;
#if VIEW == 0
    vec3 colour = srgb_encode(texture(u_raster, uv).rgb);
#elif VIEW == 1
    vec3 colour = srgb_encode(texture(u_traced, uv).rgb);
#elif VIEW == 2
    bool left = uv.x < u_divider;
    vec3 colour = srgb_encode((left != (u_swap == 1)) ? texture(u_raster, uv).rgb
                                                      : texture(u_traced, uv).rgb);
    if (abs(gl_FragCoord.x - u_divider * u_viewport.x) < 1.5) colour = vec3(1.0);
#elif VIEW == 3
    vec3 raster = srgb_encode(texture(u_raster, uv).rgb);
    vec3 d = raster - srgb_encode(texture(u_traced, uv).rgb);
    float largest = max(abs(d.r), max(abs(d.g), abs(d.b)));
    vec3 colour;
    if (u_diff_threshold > 0.0) {
        colour = largest > u_diff_threshold ? vec3(1.0) : 0.25 * raster;
    } else {
#if DIFF_MODE == 1
        float l = clamp(dot(d, vec3(0.2126, 0.7152, 0.0722)) / u_diff_scale, -1.0, 1.0);
        colour = l > 0.0 ? l * vec3(1.0, 0.25, 0.15) : -l * vec3(0.2, 0.5, 1.0);
#elif DIFF_MODE == 2
        colour = clamp(abs(d) / u_diff_scale, 0.0, 1.0);
#else
        float t = clamp(largest / u_diff_scale, 0.0, 1.0);
        colour = srgb_encode(texture(u_heat, vec2((t * 255.0 + 0.5) / 256.0, 0.5)).rgb);
#endif
    }
#elif VIEW == 4
    uint id = texture(u_ids, uv).r >> u_ids_shift;
    int index = int(id % uint(u_palette_size));
    vec3 colour = srgb_encode(texelFetch(u_palette, ivec2(index, 0), 0).rgb);
#else
    vec3 colour = srgb_encode(texture(u_explain, uv).rgb);
#endif
#if OVERLAY == 1
    vec4 rays = texture(u_overlay, uv);
    colour = mix(colour, srgb_encode(rays.rgb), rays.a);
#endif
    o_colour = vec4(colour, 1.0);
}
