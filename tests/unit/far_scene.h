#pragma once
// A small scene of every kind of shape, written with every coordinate offset by o: legal
// input far from the origin (tests/unit/test_far.cpp, the GPU tracer's tests).
#include <array>
#include <cstdio>
#include <string>

namespace rt::test {

inline std::string number(double x) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.17g", x);
    return buffer;
}

inline std::string point(double o, double x, double y, double z) {
    return "[" + number(x + o) + ", " + number(y + o) + ", " + number(z + o) + "]";
}

// A mirror ball and a stretched ball over a checker floor, a triangle, one light: every
// kind of shape, with and without a transform.
inline std::string far_json(double o) {
    return R"({"camera": {"eye": )" + point(o, 0, 2, 10) + R"(, "look_at": )" + point(o, 0, 0, 0) +
           R"(, "fov": 40}, "resolution": [160, 120],
      "materials": {"floor": {"checker": {"colors": [[0.9, 0.9, 0.9], [0.2, 0.2, 0.6]]}}},
      "lights": [{"type": "point", "position": )" +
           point(o, 5, 8, 6) + R"(}],
      "objects": [
        {"type": "sphere", "center": )" +
           point(o, 0, 0, 0) + R"(, "radius": 1.5, "material": "mirror"},
        {"type": "sphere", "radius": 0.5, "transform": {"scale": [1, 2, 1], "translate": )" +
           point(o, 2.5, 0, 0) + R"(}},
        {"type": "triangle", "vertices": [)" +
           point(o, -3, -1, -1) + ", " + point(o, -2, -1, -1) + ", " + point(o, -2.5, 1, -1) +
           R"(]},
        {"type": "mesh", "file": "tetra)" +
           number(o) + R"(.obj"},
        {"type": "mesh", "file": "tetra0.obj", "transform": {"translate": )" +
           point(o, 1.5, 1.5, -2) + R"(}},
        {"type": "plane", "normal": [0, 1, 0], "point": )" +
           point(o, 0, -1.5, 0) + R"(, "material": "floor"}]})";
}

// A tetrahedron beside the ball, in the file's world coordinates (offset by o).
inline std::string tetra_obj(double o) {
    std::string text;
    for (const auto& v : {std::array{-3.5, -1.5, 1.0}, std::array{-2.5, -1.5, 1.0},
                          std::array{-3.0, -1.5, 2.0}, std::array{-3.0, -0.5, 1.4}})
        text += "v " + number(v[0] + o) + " " + number(v[1] + o) + " " + number(v[2] + o) + "\n";
    return text + "f 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n";
}

}  // namespace rt::test
