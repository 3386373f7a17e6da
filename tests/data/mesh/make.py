#!/usr/bin/env python3
"""Writes the PLY and STL test files (tests/data/mesh, and the bad ones in tests/data/bad):
one coloured octahedron as ASCII and binary PLY (with per-vertex colours and normals) and
as ASCII and binary STL; and town.obj, rtbench's check of a ground 120 units wide with
boxes on it (tests/cli/rtbench.sh). The files are committed; this says how they were made."""
import os, random, struct, sys

here = os.path.dirname(os.path.abspath(__file__))
bad = os.path.join(here, "..", "bad")
verts = [(1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)]
colours = [(255, 0, 0), (0, 255, 255), (0, 255, 0), (255, 0, 255), (0, 0, 255), (255, 255, 0)]
faces = [(0, 2, 4), (2, 1, 4), (1, 3, 4), (3, 0, 4), (2, 0, 5), (1, 2, 5), (3, 1, 5), (0, 3, 5)]

header = ["ply", None, "comment an octahedron with a colour and a normal per vertex",
          "element vertex 6", "property float x", "property float y", "property float z",
          "property float nx", "property float ny", "property float nz",
          "property uchar red", "property uchar green", "property uchar blue",
          "element face 8", "property list uchar int vertex_indices", "end_header"]


def ply(fmt):
    h = list(header)
    h[1] = "format " + fmt + " 1.0"
    return ("\n".join(h) + "\n").encode()


with open(os.path.join(here, "octahedron_ascii.ply"), "wb") as f:
    f.write(ply("ascii"))
    for v, c in zip(verts, colours):
        f.write(("%g %g %g %g %g %g %d %d %d\n" % (v + v + c)).encode())
    for t in faces:
        f.write(("3 %d %d %d\n" % t).encode())
binary = ply("binary_little_endian")
for v, c in zip(verts, colours):
    binary += struct.pack("<6f3B", *v, *v, *c)
for t in faces:
    binary += struct.pack("<B3i", 3, *t)
with open(os.path.join(here, "octahedron_binary.ply"), "wb") as f:
    f.write(binary)
with open(os.path.join(bad, "ply_truncated.ply"), "wb") as f:
    f.write(binary[: len(binary) - 40])


def normal(t):
    a, b, c = (verts[i] for i in t)
    u = [b[k] - a[k] for k in range(3)]
    w = [c[k] - a[k] for k in range(3)]
    n = (u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0])
    length = sum(x * x for x in n) ** 0.5
    return tuple(x / length for x in n)


with open(os.path.join(here, "octahedron_ascii.stl"), "w") as f:
    f.write("solid octahedron\n")
    for t in faces:
        f.write("  facet normal %g %g %g\n    outer loop\n" % normal(t))
        for i in t:
            f.write("      vertex %g %g %g\n" % verts[i])
        f.write("    endloop\n  endfacet\n")
    f.write("endsolid octahedron\n")
stl = b"binary STL of an octahedron".ljust(80, b" ") + struct.pack("<I", len(faces))
for t in faces:
    stl += struct.pack("<3f", *normal(t)) + b"".join(struct.pack("<3f", *verts[i]) for i in t) + b"\0\0"
with open(os.path.join(here, "octahedron_binary.stl"), "wb") as f:
    f.write(stl)
with open(os.path.join(bad, "stl_truncated.stl"), "wb") as f:
    f.write(stl[:84] + stl[84:84 + 60])  # says 8 facets, holds one and a bit


def town():
    sys.path.insert(0, os.path.join(here, "..", "..", "..", "scripts"))
    from make_bench_meshes import add_box

    random.seed(3)
    vertices, faces = [], []

    def box(*corners):
        add_box(vertices, faces, *corners)

    vertices.extend([(-60, 0, -60), (60, 0, -60), (60, 0, 60), (-60, 0, 60)])
    faces.extend([(0, 1, 2), (0, 2, 3)])
    for _ in range(40):
        x, z = random.uniform(-50, 50), random.uniform(-50, 50)
        w, d, h = random.uniform(1, 6), random.uniform(1, 6), random.uniform(1, 12)
        box(x, 0, z, x + w, h, z + d)
    with open(os.path.join(here, "town.obj"), "w") as f:
        f.write("# rtbench's check (tests/cli/rtbench.sh): a ground 120 units wide and 40 boxes "
                "standing on it,\n# the class of an architectural or city model. Rays leaving a "
                "wall by the ground meet it\n# within float rounding of their start; rays leaving "
                "the ground far from the origin need\n# their start on its plane "
                "(app/bench/bench_common.cpp, on_triangle).\n")
        for v in vertices:
            f.write("v %g %g %g\n" % v)
        for a, b, c in faces:
            f.write("f %d %d %d\n" % (a + 1, b + 1, c + 1))


town()
