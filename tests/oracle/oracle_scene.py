#!/usr/bin/env python3
"""Writes one random scene, from a seed, both as an rtview JSON scene and as POV-Ray SDL.

    oracle_scene.py SEED OUT_DIR [--size WxH] [--glass-winding outward|inward|mixed]

OUT_DIR gets scene.json (with its meshes as mesh_K.obj) and scene.pov. The two describe
the same picture, so POV-Ray 3.7, an independent Whitted-style tracer, is an oracle for
rtview's tracer (docs/testing.md, "The POV-Ray oracle").

How the two models are made to agree:
- POV-Ray is left-handed: every point and direction has z negated (the matrix F =
  diag(1, 1, -1)); a transform M becomes F M F, written as a POV-Ray `matrix`. The JSON
  keeps the scale/rotate/translate form, so rtview's own reading of it is under test.
- The camera: POV-Ray's `angle` is the horizontal field of view; rtview's `fov` the
  vertical one.
- Colours are linear (`assumed_gamma 1.0`); the image is written with File_Gamma=sRGB.
- A material is a colour C with ka = a C and kd = d C (POV-Ray's pigment C, `ambient a`,
  `diffuse d`), a grey ks (`phong ks phong_size n`: both are (r.v)^n), a reflectivity
  (`reflection kr`) and a transparency (`transmit kt`, with `interior { ior }`).
- Glass is ka = kd = 0 (see tinted glass below). POV-Ray lets light through transparent
  objects; the tutorial's shadow feelers stop at them. So glass is written `no_shadow`
  and beside it an opaque twin `no_image no_reflection`: the twin casts the shadow.
- Total internal reflection: POV-Ray reflects with weight 1 and drops the surface's own
  reflection there; rtview reflects what would have been transmitted, kt, plus its own kr.
  The two agree when kr + kt = 1, so the generator's glass has kr = 1 - kt.
- Left out: checker patterns (POV-Ray's 3D unit checker is another pattern), directional
  lights (POV-Ray's parallel lights are still positioned), coloured ks (POV-Ray's phong
  is grey, or the pigment's with `metallic`), and tinted glass (POV-Ray attenuates a
  transmitting surface's ambient and diffuse light by 1 - transmit, Whitted does not).
"""

import argparse
import json
import math
import os
import random

# Closed meshes, wound outward (counter-clockwise seen from outside), around the origin.
MESHES = {
    "cube": (
        [(-0.5, -0.5, -0.5), (0.5, -0.5, -0.5), (0.5, 0.5, -0.5), (-0.5, 0.5, -0.5),
         (-0.5, -0.5, 0.5), (0.5, -0.5, 0.5), (0.5, 0.5, 0.5), (-0.5, 0.5, 0.5)],
        [(0, 3, 2), (0, 2, 1), (4, 5, 6), (4, 6, 7), (0, 1, 5), (0, 5, 4),
         (3, 7, 6), (3, 6, 2), (0, 4, 7), (0, 7, 3), (1, 2, 6), (1, 6, 5)],
    ),
    "tetrahedron": (
        [(1, 1, 1), (1, -1, -1), (-1, 1, -1), (-1, -1, 1)],
        [(0, 1, 2), (0, 3, 1), (0, 2, 3), (1, 3, 2)],
    ),
    "octahedron": (
        [(1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)],
        [(0, 2, 4), (4, 2, 1), (1, 2, 5), (5, 2, 0),
         (4, 3, 0), (1, 3, 4), (5, 3, 1), (0, 3, 5)],
    ),
    "prism": (  # a triangular prism along z
        [(0, 0.8, -0.5), (-0.7, -0.4, -0.5), (0.7, -0.4, -0.5),
         (0, 0.8, 0.5), (-0.7, -0.4, 0.5), (0.7, -0.4, 0.5)],
        [(0, 2, 1), (3, 4, 5), (0, 1, 4), (0, 4, 3), (1, 2, 5), (1, 5, 4), (2, 0, 3), (2, 3, 5)],
    ),
}


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def check_outward(name):
    """Every face's normal points away from the mesh's centre (so the tables are right)."""
    verts, faces = MESHES[name]
    centre = tuple(sum(v[k] for v in verts) / len(verts) for k in range(3))
    for f in faces:
        a, b, c = (verts[i] for i in f)
        n = cross(sub(b, a), sub(c, a))
        assert dot(n, sub(a, centre)) > 0, (name, f)


def matmul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(3)) for j in range(3)] for i in range(3)]


def rotation(axis, degrees):
    c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
    if axis == 0:
        return [[1, 0, 0], [0, c, -s], [0, s, c]]
    if axis == 1:
        return [[c, 0, s], [0, 1, 0], [-s, 0, c]]
    return [[c, -s, 0], [s, c, 0], [0, 0, 1]]


def linear_part(scale, rotate):
    """Rz Ry Rx S, the documented order (docs/scene-format.md, transform)."""
    m = [[scale[0], 0, 0], [0, scale[1], 0], [0, 0, scale[2]]]
    for axis in range(3):
        m = matmul(rotation(axis, rotate[axis]), m)
    return m


def pov_vec(v):
    """A point or direction in POV-Ray's left-handed frame: z negated."""
    return "<%.9g, %.9g, %.9g>" % (v[0], v[1], -v[2])


def pov_matrix(lin, translate):
    """F M F for F = diag(1, 1, -1), in POV-Ray's row-vector layout (p' = p M)."""
    f = (1, 1, -1)
    g = [[f[i] * lin[i][j] * f[j] for j in range(3)] for i in range(3)]
    t = (translate[0], translate[1], -translate[2])
    entries = [g[j][i] for i in range(3) for j in range(3)] + list(t)
    return "matrix <" + ", ".join("%.9g" % e for e in entries) + ">"


class Generator:
    def __init__(self, seed, width, height, winding):
        self.rng = random.Random(seed)
        self.seed = seed
        self.width, self.height = width, height
        self.winding = winding
        self.materials = {}
        self.objects = []  # (json object, pov text)
        self.meshes = {}  # file name -> obj text

    def u(self, lo, hi):
        return round(self.rng.uniform(lo, hi), 4)

    def colour(self):
        return [self.u(0.15, 1.0) for _ in range(3)]

    # --- materials ------------------------------------------------------------------
    def material(self, kind):
        name = "m%d" % len(self.materials)
        c = self.colour()
        mat = {"c": c, "a": 0.0, "d": 0.0, "ks": 0.0, "n": 32.0, "kr": 0.0, "kt": 0.0, "ior": 1.5}
        if kind == "ambient":
            mat["a"] = self.u(0.5, 1.0)
        elif kind == "diffuse":
            mat["a"], mat["d"] = self.u(0.0, 0.4), self.u(0.4, 1.0)
        elif kind == "phong":
            mat["a"], mat["d"] = self.u(0.0, 0.3), self.u(0.3, 0.8)
            mat["ks"], mat["n"] = self.u(0.2, 0.9), self.u(8, 200)
        elif kind == "mirror":
            mat["a"], mat["d"] = self.u(0.0, 0.1), self.u(0.0, 0.2)
            mat["ks"], mat["n"] = self.u(0.0, 0.8), self.u(50, 300)
            mat["kr"] = self.u(0.5, 0.95)
        elif kind == "glass":
            mat["ks"], mat["n"] = self.u(0.0, 0.9), self.u(50, 300)
            mat["kt"] = self.u(0.6, 0.95)
            mat["kr"] = round(1.0 - mat["kt"], 4)  # see the module's note on total internal reflection
            mat["ior"] = self.u(1.1, 2.4)
        self.materials[name] = mat
        return name

    def json_material(self, m):
        c = m["c"]
        return {
            "ka": [round(m["a"] * x, 6) for x in c],
            "kd": [round(m["d"] * x, 6) for x in c],
            "ks": m["ks"],
            "shininess": m["n"],
            "reflectivity": m["kr"],
            "transparency": m["kt"],
            "ior": m["ior"],
        }

    def pov_texture(self, m):
        c = m["c"]
        pigment = "pigment { rgbt <%g, %g, %g, %g> }" % (c[0], c[1], c[2], m["kt"])
        finish = "finish { ambient %g diffuse %g phong %g phong_size %g reflection { %g } }" % (
            m["a"], m["d"], m["ks"], m["n"], m["kr"])
        interior = " interior { ior %g }" % m["ior"] if m["kt"] > 0 else ""
        return pigment + " " + finish + interior

    # --- objects ----------------------------------------------------------------------
    def transform(self, scale_range, allow_negative):
        s = [self.u(*scale_range) for _ in range(3)]
        if allow_negative and self.rng.random() < 0.3:
            s[self.rng.randrange(3)] *= -1
        r = [self.u(-180, 180) for _ in range(3)]
        return s, r

    def place(self, radius):
        """A spot on or above the floor, inside the camera's view, not too near others."""
        for _ in range(50):
            p = (self.u(-2.2, 2.2), self.u(radius, radius + 1.0), self.u(-2.2, 2.2))
            if all(math.dist(p, q) > radius + r + 0.1 for q, r in self.placed):
                self.placed.append((p, radius))
                return p
        self.placed.append((p, radius))
        return p

    def add(self, json_obj, pov_obj, mat_name):
        m = self.materials[mat_name]
        json_obj["material"] = mat_name
        if m["kt"] > 0:
            # The tutorial's glass casts a shadow; POV-Ray's does not. A twin casts it.
            twin = pov_obj.replace("@TEXTURE@", "pigment { rgb 0 } no_image no_reflection")
            pov_obj = pov_obj.replace("@TEXTURE@", self.pov_texture(m) + " no_shadow")
            pov_obj += "\n" + twin
        else:
            pov_obj = pov_obj.replace("@TEXTURE@", self.pov_texture(m))
        self.objects.append((json_obj, pov_obj))

    def sphere(self, mat):
        transformed = self.rng.random() < 0.5
        if not transformed:
            r = self.u(0.3, 0.9)
            c = self.place(r)
            self.add({"type": "sphere", "center": list(c), "radius": r},
                     "sphere { %s, %g @TEXTURE@ }" % (pov_vec(c), r), mat)
            return
        s, rot = self.transform((0.3, 0.9), True)
        t = self.place(max(abs(x) for x in s))
        lin = linear_part(s, rot)
        self.add({"type": "sphere", "transform": {"scale": s, "rotate": rot, "translate": list(t)}},
                 "sphere { <0, 0, 0>, 1 @TEXTURE@ %s }" % pov_matrix(lin, t), mat)

    def mesh(self, mat):
        shape = self.rng.choice(sorted(MESHES))
        verts, faces = MESHES[shape]
        inward = self.winding == "inward" or (self.winding == "mixed" and self.rng.random() < 0.5)
        if inward:
            faces = [(a, c, b) for a, b, c in faces]
        file = "mesh_%d.obj" % len(self.meshes)
        lines = ["# %s, wound %s (oracle seed %d)" % (shape, "inward" if inward else "outward", self.seed)]
        lines += ["v %g %g %g" % v for v in verts]
        lines += ["f %d %d %d" % (a + 1, b + 1, c + 1) for a, b, c in faces]
        self.meshes[file] = "\n".join(lines) + "\n"
        s, rot = self.transform((0.4, 1.0), True)
        t = self.place(max(abs(x) for x in s) * 1.2)
        lin = linear_part(s, rot)
        tris = " ".join("triangle { %s, %s, %s }" % tuple(pov_vec(verts[i]) for i in f) for f in faces)
        # Its triangles in the mesh's own frame (z negated), then F M F: the same as F M.
        self.add({"type": "mesh", "file": file,
                  "transform": {"scale": s, "rotate": rot, "translate": list(t)}},
                 "mesh { %s inside_vector <0, 0, 1> @TEXTURE@ %s }" % (tris, pov_matrix(lin, t)), mat)

    def triangle(self, mat):
        centre = self.place(0.8)
        v = [tuple(round(centre[k] + self.u(-0.9, 0.9), 4) for k in range(3)) for _ in range(3)]
        n = cross(sub(v[1], v[0]), sub(v[2], v[0]))
        if dot(n, n) < 0.05:  # nearly collinear: skip
            return
        self.add({"type": "triangle", "vertices": [list(p) for p in v]},
                 "triangle { %s, %s, %s @TEXTURE@ }" % tuple(pov_vec(p) for p in v), mat)

    # --- the scene ----------------------------------------------------------------------
    def build(self):
        rng = self.rng
        self.placed = []
        azimuth, elevation = rng.uniform(0, 360), rng.uniform(12, 40)
        distance = rng.uniform(6.5, 9.0)
        el, az = math.radians(elevation), math.radians(azimuth)
        eye = [round(distance * math.cos(el) * math.sin(az), 4), round(distance * math.sin(el), 4),
               round(distance * math.cos(el) * math.cos(az), 4)]
        target = [self.u(-0.4, 0.4), self.u(0.3, 0.8), self.u(-0.4, 0.4)]
        fov = self.u(35, 55)
        self.camera = (eye, target, fov)
        self.background = [self.u(0.0, 0.6) for _ in range(3)]
        self.ambient = self.u(0.05, 0.4)
        self.lights = []
        for _ in range(rng.randint(1, 3)):
            pos = [self.u(-6, 6), self.u(3, 9), self.u(-6, 6)]
            self.lights.append((pos, [self.u(0.3, 0.8) for _ in range(3)]))

        floor = self.material(rng.choice(["diffuse", "phong", "mirror"]) if rng.random() < 0.3 else "diffuse")
        self.add({"type": "plane", "normal": [0, 1, 0], "offset": 0},
                 "plane { <0, 1, 0>, 0 @TEXTURE@ }", floor)
        if rng.random() < 0.4:  # a tilted back wall
            n = [self.u(-0.3, 0.3), self.u(0.0, 0.3), 1.0]
            length = math.sqrt(dot(n, n))
            n = [round(x / length, 6) for x in n]
            offset = round(-self.u(3.5, 5), 4)
            wall = self.material(rng.choice(["ambient", "diffuse", "phong", "mirror"]))
            self.add({"type": "plane", "normal": n, "offset": offset},
                     "plane { %s, %g @TEXTURE@ }" % (pov_vec(n), offset), wall)
        kinds = ["ambient", "diffuse", "phong", "phong", "mirror", "glass", "glass"]
        for _ in range(rng.randint(3, 6)):
            mat = self.material(rng.choice(kinds))
            rng.choice([self.sphere, self.sphere, self.mesh, self.mesh, self.triangle])(mat)

    def json_scene(self):
        eye, target, fov = self.camera
        return {
            "camera": {"eye": eye, "look_at": target, "up": [0, 1, 0], "fov": fov},
            "resolution": [self.width, self.height],
            "background": self.background,
            "ambient": self.ambient,
            "lights": [{"type": "point", "position": p, "color": c} for p, c in self.lights],
            "materials": {k: self.json_material(m) for k, m in self.materials.items()},
            "objects": [j for j, _ in self.objects],
        }

    def pov_scene(self, max_depth):
        eye, target, fov = self.camera
        aspect = self.width / self.height
        angle = math.degrees(2 * math.atan(math.tan(math.radians(fov) / 2) * aspect))
        out = [
            "// oracle seed %d: the same scene as scene.json, for POV-Ray 3.7" % self.seed,
            "#version 3.7;",
            # max_trace_level counts the camera ray; rtview's depth counts the bounces after it.
            "global_settings { assumed_gamma 1.0 max_trace_level %d adc_bailout 0"
            " ambient_light rgb %g }" % (max_depth + 1, self.ambient),
            "camera { perspective location %s look_at %s sky <0, 1, 0> right x*%.9g up y angle %.9g }"
            % (pov_vec(eye), pov_vec(target), aspect, angle),
            "background { rgb <%g, %g, %g> }" % tuple(self.background),
        ]
        for p, c in self.lights:
            out.append("light_source { %s rgb <%g, %g, %g> }" % ((pov_vec(p),) + tuple(c)))
        out += [p for _, p in self.objects]
        return "\n".join(out) + "\n"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("seed", type=int)
    ap.add_argument("out_dir")
    ap.add_argument("--size", default="200x150")
    ap.add_argument("--max-depth", type=int, default=5)
    ap.add_argument("--glass-winding", choices=["outward", "inward", "mixed"], default="mixed")
    args = ap.parse_args()
    for name in MESHES:
        check_outward(name)
    width, height = (int(x) for x in args.size.split("x"))
    gen = Generator(args.seed, width, height, args.glass_winding)
    gen.build()
    os.makedirs(args.out_dir, exist_ok=True)
    with open(os.path.join(args.out_dir, "scene.json"), "w") as f:
        json.dump(gen.json_scene(), f, indent=1)
    with open(os.path.join(args.out_dir, "scene.pov"), "w") as f:
        f.write(gen.pov_scene(args.max_depth))
    for name, text in gen.meshes.items():
        with open(os.path.join(args.out_dir, name), "w") as f:
            f.write(text)


if __name__ == "__main__":
    main()
