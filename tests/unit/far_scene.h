#pragma once
// A small scene of every kind of shape, written with every coordinate offset by o (and
// every length scaled by s): legal input far from the origin, or tiny
// (tests/unit/test_far.cpp, the GPU tracer's tests).
#include <array>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "test_util.h"

namespace rt::test {

inline std::string number(double x) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.17g", x);
    return buffer;
}

inline std::string point(double o, double x, double y, double z, double s = 1.0) {
    return "[" + number(s * x + o) + ", " + number(s * y + o) + ", " + number(s * z + o) + "]";
}

// A mirror ball and a stretched ball over a checker floor, a triangle, one light: every
// kind of shape, with and without a transform. Its meshes are tetra{o}.obj and tetra0.obj
// beside it, written by tetra_obj(o, s) and tetra_obj(0, s). With `uvn` the camera is
// given by its axes u, v, n and view plane (no point it looks at), the same view.
inline std::string far_json(double o, double s = 1.0, bool uvn = false) {
    const auto at = [&](double x, double y, double z) { return point(o, x, y, z, s); };
    const std::string view = uvn ? R"(, "u": [1, 0, 0], "v": [0, 10, -2], "n": [0, 2, 10], )"
                                   R"("H": 0.36397023426620234})"
                                 : R"(, "look_at": )" + at(0, 0, 0) + R"(, "fov": 40})";
    return R"({"camera": {"eye": )" + at(0, 2, 10) + view + R"(, "resolution": [160, 120],
      "materials": {"floor": {"checker": {"colors": [[0.9, 0.9, 0.9], [0.2, 0.2, 0.6]], "scale": )" +
           number(s) + R"(}}},
      "lights": [{"type": "point", "position": )" +
           at(5, 8, 6) + R"(}],
      "objects": [
        {"type": "sphere", "center": )" +
           at(0, 0, 0) + R"(, "radius": )" + number(1.5 * s) + R"(, "material": "mirror"},
        {"type": "sphere", "radius": )" +
           number(0.5 * s) + R"(, "transform": {"scale": [1, 2, 1], "translate": )" +
           at(2.5, 0, 0) + R"(}},
        {"type": "triangle", "vertices": [)" +
           at(-3, -1, -1) + ", " + at(-2, -1, -1) + ", " + at(-2.5, 1, -1) +
           R"(]},
        {"type": "mesh", "file": "tetra)" +
           number(o) + R"(.obj"},
        {"type": "mesh", "file": "tetra0.obj", "transform": {"translate": )" +
           at(1.5, 1.5, -2) + R"(}},
        {"type": "plane", "normal": [0, 1, 0], "point": )" +
           at(0, -1.5, 0) + R"(, "material": "floor"}]})";
}

// A tetrahedron beside the ball, in the file's world coordinates (offset by o, scaled by s).
inline std::string tetra_obj(double o, double s = 1.0) {
    std::string text;
    for (const auto& v : {std::array{-3.5, -1.5, 1.0}, std::array{-2.5, -1.5, 1.0},
                          std::array{-3.0, -1.5, 2.0}, std::array{-3.0, -0.5, 1.4}})
        text += "v " + number(s * v[0] + o) + " " + number(s * v[1] + o) + " " +
                number(s * v[2] + o) + "\n";
    return text + "f 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n";
}

// The Stanford bunny with every coordinate scaled by s, then offset by o, written with
// `digits` significant digits (17: full precision).
inline std::string bunny_obj(double s, double o, int digits = 17) {
    const auto number = [&](double x) {
        char buffer[64];
        std::snprintf(buffer, sizeof buffer, "%.*g", digits, x);
        return std::string(buffer);
    };
    std::ifstream in(source_dir() / "assets/models/stanford-bunny.obj");
    std::ostringstream out;
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("v ", 0) == 0) {
            std::istringstream v(line.substr(2));
            double x, y, z;
            v >> x >> y >> z;
            out << "v " << number(s * x + o) << " " << number(s * y + o) << " " << number(s * z + o)
                << "\n";
        } else {
            out << line << "\n";
        }
    }
    return out.str();
}

}  // namespace rt::test
