#!/usr/bin/env python3
"""Writes the meshes docs/BENCHMARKS.md times besides the shipped ones, each a kind of
real model the shipped ones do not cover:

  vase.obj     120,000 long, thin triangles (a surface of revolution, 1200 segments
               around, 50 rings): a lathed or CAD model
  terrain.obj  96,800 triangles of a noisy height field (220 x 220 cells): a landscape,
               rays grazing it
  bunny4.obj   277,804 triangles: the Stanford bunny with each triangle split in four at
               its edges' midpoints (a scan at four times the resolution)
  city.obj     122,402 triangles: 3,000 boxes and 150 spheres on a ground of two triangles
               120 units wide: an architectural or city model, triangles of every size,
               hits up to 85 units from the origin
  tree.obj     96,960 triangles: a trunk and 48,000 leaves (quads of two triangles, turned
               every way) in 600 clusters in a crown: foliage, small triangles overlapping
  soup.obj     100,000 triangles of at most 0.02 units at random in a unit cube: the worst
               of overlap (a particle cloud), not a model
  hall.obj     about 100,000 triangles: a closed hall 30 units long with fluted columns,
               arches, curtains and tables; hall.json looks at it from inside (every ray
               hits, feelers start among the columns): an interior, as Sponza is
  fan.obj      60,000 slivers meeting at one vertex, a wavy disc: the cap of a finely
               tessellated cylinder or a sphere's pole taken to the extreme
  straws.obj   60,000 needles 3 units long and about 0.007 across, crossing at random in
               a 4-unit cube: thin triangles at every angle (hay, hair, grass)
  twist.obj    60,000 slivers 6 units long, each a side of a tube twisted by a quarter
               turn: long triangles whose boxes all overlap

Usage: scripts/make_bench_meshes.py OUT_DIR [BUNNY_OBJ]
The same files on every run (a fixed seed)."""
import math
import os
import random
import sys


def write_obj(path, vertices, faces):
    with open(path, "w") as f:
        for v in vertices:
            f.write("v %.6f %.6f %.6f\n" % v)
        for a, b, c in faces:
            f.write("f %d %d %d\n" % (a + 1, b + 1, c + 1))
    print("%s: %d vertices, %d triangles" % (path, len(vertices), len(faces)))


def vase(around=1200, rings=50):
    vertices, faces = [], []
    for j in range(rings + 1):
        y = j / rings * 3.0
        r = 0.6 + 0.3 * math.sin(y * 2.1) + 0.1 * math.cos(y * 5)
        for i in range(around):
            t = 2 * math.pi * i / around
            vertices.append((r * math.cos(t), y, r * math.sin(t)))
    for j in range(rings):
        for i in range(around):
            a, b = j * around + i, j * around + (i + 1) % around
            faces += [(a, b, b + around), (a, b + around, a + around)]
    return vertices, faces


def terrain(n=220, seed=1):
    rng = random.Random(seed)
    vertices, faces = [], []
    for j in range(n + 1):
        for i in range(n + 1):
            x, z = i / n * 10 - 5, j / n * 10 - 5
            h = (0.6 * math.sin(x * 1.3) * math.cos(z * 1.1) + 0.25 * math.sin(x * 4.1 + z * 3.3) +
                 0.05 * rng.random())
            vertices.append((x, h, z))
    for j in range(n):
        for i in range(n):
            a = j * (n + 1) + i
            c = a + n + 1
            faces += [(a, c, a + 1), (a + 1, c, c + 1)]
    return vertices, faces


def add_box(vertices, faces, x0, y0, z0, x1, y1, z1):
    """An axis-aligned box from (x0, y0, z0) to (x1, y1, z1), twelve triangles (also
    tests/data/mesh/make.py's town)."""
    b = len(vertices)
    vertices.extend((x, y, z) for x in (x0, x1) for y in (y0, y1) for z in (z0, z1))
    for a, c, d, e in [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4),
                       (1, 5, 7, 3)]:
        faces.extend([(b + a, b + c, b + d), (b + a, b + d, b + e)])


def city(seed=7):
    rng = random.Random(seed)
    vertices, faces = [], []

    def box(*corners):
        add_box(vertices, faces, *corners)

    def sphere(cx, cy, cz, r, n=12):
        b = len(vertices)
        for j in range(n + 1):
            theta = math.pi * j / n
            for i in range(2 * n):
                phi = math.pi * i / n
                vertices.append((cx + r * math.sin(theta) * math.cos(phi), cy + r * math.cos(theta),
                                 cz + r * math.sin(theta) * math.sin(phi)))
        for j in range(n):
            for i in range(2 * n):
                a, c = b + j * 2 * n + i, b + j * 2 * n + (i + 1) % (2 * n)
                faces.extend([(a, c, c + 2 * n), (a, c + 2 * n, a + 2 * n)])

    vertices.extend([(-60, 0, -60), (60, 0, -60), (60, 0, 60), (-60, 0, 60)])
    faces.extend([(0, 1, 2), (0, 2, 3)])
    for _ in range(3000):
        x, z = rng.uniform(-50, 50), rng.uniform(-50, 50)
        w, d, h = rng.uniform(0.5, 3), rng.uniform(0.5, 3), rng.expovariate(1 / 4) + 0.5
        box(x, 0, z, x + w, h, z + d)
    for _ in range(150):
        sphere(rng.uniform(-50, 50), rng.uniform(0.2, 1), rng.uniform(-50, 50), rng.uniform(0.1, 0.6))
    return vertices, faces


def unit_vector(rng):
    while True:
        p = [rng.uniform(-1, 1) for _ in range(3)]
        n = math.sqrt(sum(x * x for x in p))
        if 0 < n <= 1:
            return [x / n for x in p]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def scaled(v, length):
    n = math.sqrt(sum(x * x for x in v)) or 1.0
    return [x / n * length for x in v]


def tree(seed=5):
    rng = random.Random(seed)
    vertices, faces = [], []
    around, rings = 24, 20
    for j in range(rings + 1):
        y, r = j / rings * 4, 0.3 * (1 - 0.5 * j / rings)
        for i in range(around):
            t = 2 * math.pi * i / around
            vertices.append((r * math.cos(t), y, r * math.sin(t)))
    for j in range(rings):
        for i in range(around):
            a, c = j * around + i, j * around + (i + 1) % around
            faces += [(a, c, c + around), (a, c + around, a + around)]
    for _ in range(600):
        d, r = unit_vector(rng), rng.random() ** 0.5
        cluster = [d[0] * 2.5 * r, 5 + d[1] * 1.8 * r, d[2] * 2.5 * r]
        for _ in range(80):
            c = [x + rng.gauss(0, 0.25) for x in cluster]
            n = unit_vector(rng)
            u = scaled(cross(n, unit_vector(rng)), 0.06)
            v = scaled(cross(n, u), 0.03)
            b = len(vertices)
            for su, sv in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
                vertices.append(tuple(c[k] + su * u[k] + sv * v[k] for k in range(3)))
            faces += [(b, b + 1, b + 2), (b, b + 2, b + 3)]
    return vertices, faces


def soup(count=100000, seed=11):
    rng = random.Random(seed)
    vertices, faces = [], []
    for i in range(count):
        c = [rng.random() for _ in range(3)]
        for _ in range(3):
            vertices.append(tuple(x + rng.uniform(-0.01, 0.01) for x in c))
        faces.append((3 * i, 3 * i + 1, 3 * i + 2))
    return vertices, faces


def fan(count=60000):
    vertices, faces = [(0.0, 0.0, 0.0)], []
    for i in range(count):
        a = 2 * math.pi * i / count
        vertices.append((4 * math.cos(a), 0.3 * math.sin(5 * a), 4 * math.sin(a)))
        faces.append((0, 1 + i, 1 + (i + 1) % count))
    return vertices, faces


def straws(count=60000, seed=3):
    rng = random.Random(seed)
    vertices, faces = [], []
    for _ in range(count):
        c = [rng.uniform(-2, 2) for _ in range(3)]
        d = [rng.gauss(0, 1) for _ in range(3)]
        length = math.sqrt(sum(x * x for x in d))
        d = [x / length * 1.5 for x in d]
        w = [rng.gauss(0, 1) * 0.004 for _ in range(3)]
        k = len(vertices)
        vertices.append(tuple(c[q] - d[q] for q in range(3)))
        vertices.append(tuple(c[q] + d[q] for q in range(3)))
        vertices.append(tuple(c[q] + d[q] + w[q] for q in range(3)))
        faces.append((k, k + 1, k + 2))
    return vertices, faces


def twist(count=30000):
    vertices, faces = [], []
    for i in range(count):
        a = 2 * math.pi * i / count
        vertices.append((math.cos(a), -3.0, math.sin(a)))
        vertices.append((math.cos(a + math.pi / 2), 3.0, math.sin(a + math.pi / 2)))
    for i in range(count):
        j = (i + 1) % count
        faces.append((2 * i, 2 * j, 2 * i + 1))
        faces.append((2 * j, 2 * j + 1, 2 * i + 1))
    return vertices, faces


def add_grid(vertices, faces, corner, u, v, nu, nv, bulge=None):
    """A patch from `corner` along u and v in nu x nv quads; bulge(s, t) -> offset vector."""
    b = len(vertices)
    for j in range(nv + 1):
        for i in range(nu + 1):
            s, t = i / nu, j / nv
            d = bulge(s, t) if bulge else (0, 0, 0)
            vertices.append(tuple(corner[k] + s * u[k] + t * v[k] + d[k] for k in range(3)))
    for j in range(nv):
        for i in range(nu):
            a = b + j * (nu + 1) + i
            faces.extend([(a, a + 1, a + nu + 2), (a, a + nu + 2, a + nu + 1)])


def add_tube(vertices, faces, path, radius, around):
    """A tube along the points of `path`, its radius radius(k, angle) at point k."""
    b = len(vertices)
    for k, p in enumerate(path):
        q = path[min(k + 1, len(path) - 1)]
        o = path[max(k - 1, 0)]
        axis = scaled([q[i] - o[i] for i in range(3)], 1.0)
        side = scaled(cross(axis, [0.0, 0.0, 1.0] if abs(axis[2]) < 0.9 else [1.0, 0.0, 0.0]), 1.0)
        up = cross(side, axis)
        for i in range(around):
            a = 2 * math.pi * i / around
            r = radius(k, a)
            vertices.append(tuple(p[j] + r * (math.cos(a) * side[j] + math.sin(a) * up[j])
                                  for j in range(3)))
    for k in range(len(path) - 1):
        for i in range(around):
            a, c = b + k * around + i, b + k * around + (i + 1) % around
            faces.extend([(a, c, c + around), (a, c + around, a + around)])


def hall(seed=3):
    rng = random.Random(seed)
    vertices, faces = [], []
    x0, x1, z0, z1, top = -15.0, 15.0, -8.0, 8.0, 10.0
    add_grid(vertices, faces, (x0, 0, z0), (30, 0, 0), (0, 0, 16), 60, 32)  # floor
    add_grid(vertices, faces, (x0, top, z0), (30, 0, 0), (0, 0, 16), 60, 32)  # ceiling
    for z in (z0, z1):
        add_grid(vertices, faces, (x0, 0, z), (30, 0, 0), (0, top, 0), 60, 20)
    for x in (x0, x1):
        add_grid(vertices, faces, (x, 0, z0), (0, 0, 16), (0, top, 0), 32, 20)
    for z in (-4.0, 4.0):  # two rows of fluted columns, arches between them
        xs = [-12.0 + 24.0 * i / 9 for i in range(10)]
        for x in xs:
            add_tube(vertices, faces, [(x, 7.0 * k / 30, z) for k in range(31)],
                     lambda k, a: 0.5 + 0.03 * math.cos(16 * a), 48)
            add_box(vertices, faces, x - 0.7, 7.0, z - 0.7, x + 0.7, 7.4, z + 0.7)
        for xa, xb in zip(xs, xs[1:]):
            mid, half = (xa + xb) / 2, (xb - xa) / 2
            arc = [(mid - half * math.cos(math.pi * k / 24), 7.4 + 0.8 * half * math.sin(math.pi * k / 24), z)
                   for k in range(25)]
            add_tube(vertices, faces, arc, lambda k, a: 0.3, 12)
    for z, sign in ((z0 + 0.3, 1), (z1 - 0.3, -1)):  # curtains along the long walls
        add_grid(vertices, faces, (x0 + 1, 1.0, z), (28, 0, 0), (0, 8, 0), 80, 30,
                 lambda s, t: (0, 0, sign * 0.25 * (1 + math.sin(2 * math.pi * 18 * s))))
    for _ in range(30):  # tables with a ball on each
        x, z = rng.uniform(-13, 13), rng.uniform(-2.5, 2.5)
        add_box(vertices, faces, x - 0.8, 0.8, z - 0.5, x + 0.8, 0.9, z + 0.5)
        for dx in (-0.7, 0.7):
            for dz in (-0.4, 0.4):
                add_box(vertices, faces, x + dx - 0.05, 0, z + dz - 0.05, x + dx + 0.05, 0.8, z + dz + 0.05)
        r = rng.uniform(0.15, 0.35)
        add_tube(vertices, faces, [(x, 0.9 + r - r * math.cos(math.pi * k / 12), z) for k in range(13)],
                 lambda k, a, r=r: max(1e-3, r * math.sin(math.pi * k / 12)), 24)
    return vertices, faces


HALL_SCENE = """{
  "camera": { "eye": [-13, 3, 0.5], "look_at": [10, 2.5, -0.5], "up": [0, 1, 0], "fov": 60 },
  "resolution": [1280, 720],
  "lights": [
    { "type": "point", "position": [0, 9, 0], "color": 0.7 },
    { "type": "point", "position": [-8, 8, 5], "color": 0.4 }
  ],
  "objects": [ { "name": "hall", "type": "mesh", "file": "hall.obj" } ]
}
"""


def subdivided(path):
    vertices, faces = [], []
    with open(path) as f:
        for line in f:
            p = line.split()
            if p and p[0] == "v":
                vertices.append(tuple(map(float, p[1:4])))
            elif p and p[0] == "f":
                faces.append(tuple(int(x.split("/")[0]) - 1 for x in p[1:4]))
    middle = {}

    def mid(a, b):
        key = (min(a, b), max(a, b))
        if key not in middle:
            vertices.append(tuple((x + y) / 2 for x, y in zip(vertices[a], vertices[b])))
            middle[key] = len(vertices) - 1
        return middle[key]

    out = []
    for a, b, c in faces:
        ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
        out += [(a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca)]
    return vertices, out


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    out = sys.argv[1]
    here = os.path.dirname(os.path.abspath(__file__))
    bunny = sys.argv[2] if len(sys.argv) > 2 else os.path.join(here, "..", "assets", "models",
                                                               "stanford-bunny.obj")
    os.makedirs(out, exist_ok=True)
    write_obj(os.path.join(out, "vase.obj"), *vase())
    write_obj(os.path.join(out, "terrain.obj"), *terrain())
    write_obj(os.path.join(out, "bunny4.obj"), *subdivided(bunny))
    write_obj(os.path.join(out, "city.obj"), *city())
    write_obj(os.path.join(out, "tree.obj"), *tree())
    write_obj(os.path.join(out, "soup.obj"), *soup())
    write_obj(os.path.join(out, "hall.obj"), *hall())
    write_obj(os.path.join(out, "fan.obj"), *fan())
    write_obj(os.path.join(out, "straws.obj"), *straws())
    write_obj(os.path.join(out, "twist.obj"), *twist())
    with open(os.path.join(out, "hall.json"), "w") as f:
        f.write(HALL_SCENE)


if __name__ == "__main__":
    main()
