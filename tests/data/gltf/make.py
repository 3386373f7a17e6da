#!/usr/bin/env python3
"""Writes the hand-made glTF test files (tests/data/gltf and the glTF cases of
tests/data/bad). Run from anywhere; the files are committed, this says how they were made."""
import base64, json, math, os, struct

here = os.path.dirname(os.path.abspath(__file__))
bad = os.path.join(here, "..", "bad")

# A unit square in the xy plane (two triangles, normals +z) and a tetrahedron without
# normals (flat-shaded).
square_pos = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]
square_nrm = [(0, 0, 1)] * 4
square_idx = [0, 1, 2, 0, 2, 3]
tetra_pos = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
tetra_idx = [0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3]


def pack(fmt, values):
    return b"".join(struct.pack(fmt, *v) if isinstance(v, tuple) else struct.pack(fmt, v) for v in values)


def model(count_override=None, required=None, cycle=False, buffer_uri=None, colours=False):
    chunks = [pack("<3f", square_pos), pack("<3f", square_nrm), pack("<H", square_idx) + b"\0\0",
              pack("<3f", tetra_pos), pack("<H", tetra_idx)]
    if colours:  # COLOR_0 of the square: normalised bytes, RGBA
        chunks.append(pack("<4B", [(255, 0, 0, 255), (0, 255, 0, 255), (0, 0, 255, 255), (255, 255, 255, 255)]))
    data, views, offset = b"", [], 0
    for c in chunks:
        views.append({"buffer": 0, "byteOffset": offset, "byteLength": len(c)})
        data += c
        offset += len(c)
    views[2]["byteLength"] = 12  # the padding is not part of the indices
    acc = [
        {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
         "min": [0, 0, 0], "max": [1, 1, 0]},
        {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC3"},
        {"bufferView": 2, "componentType": 5123, "count": 6, "type": "SCALAR"},
        {"bufferView": 3, "componentType": 5126, "count": 4, "type": "VEC3",
         "min": [0, 0, 0], "max": [1, 1, 1]},
        {"bufferView": 4, "componentType": 5123, "count": 12, "type": "SCALAR"},
    ]
    if count_override:
        acc[0]["count"] = count_override
    if colours:
        acc.append({"bufferView": 5, "componentType": 5121, "normalized": True, "count": 4, "type": "VEC4"})
    s = math.sin(math.radians(15)); c = math.cos(math.radians(15))   # 30 degrees about y
    s2 = math.sin(math.radians(22.5)); c2 = math.cos(math.radians(22.5))  # 45 degrees about z
    doc = {
        "asset": {"version": "2.0", "generator": "rtview tests/data/gltf/make.py"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [
            {"name": "parent", "translation": [1, 2, 3], "rotation": [0, s, 0, c], "children": [1, 2]},
            {"name": "square", "mesh": 0, "scale": [2, 0.5, 1], "rotation": [0, 0, s2, c2],
             "translation": [0.5, 0, 0]},
            {"name": "tetra", "mesh": 1, "matrix": [1, 0, 0, 0, 0, 3, 0, 0, 0, 0, 1, 0, -2, 0, 0, 1]},
        ],
        "meshes": [
            {"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 2, "material": 0}]},
            {"primitives": [{"attributes": {"POSITION": 3}, "indices": 4, "material": 1}]},
        ],
        "materials": [
            {"name": "red plastic", "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.1, 0.1, 1],
                                                              "metallicFactor": 0, "roughnessFactor": 0.5}},
            {"name": "gold mirror", "pbrMetallicRoughness": {"baseColorFactor": [1.0, 0.8, 0.3, 1],
                                                              "metallicFactor": 1, "roughnessFactor": 0.4}},
        ],
        "accessors": acc,
        "bufferViews": views,
        "buffers": [{"byteLength": len(data),
                     "uri": buffer_uri or "data:application/octet-stream;base64," + base64.b64encode(data).decode()}],
    }
    if colours:
        doc["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"] = 5
    if required:
        doc["extensionsUsed"] = [required]
        doc["extensionsRequired"] = [required]
    if cycle:
        doc["nodes"][1]["children"] = [0]
    return doc, data


def write_json(path, doc):
    with open(path, "w") as f:
        json.dump(doc, f, indent=1)
        f.write("\n")


def glb(doc, data):
    doc = json.loads(json.dumps(doc))
    del doc["buffers"][0]["uri"]
    text = json.dumps(doc).encode()
    text += b" " * (-len(text) % 4)
    data += b"\0" * (-len(data) % 4)
    body = struct.pack("<II", len(text), 0x4E4F534A) + text + struct.pack("<II", len(data), 0x004E4942) + data
    return struct.pack("<III", 0x46546C67, 2, 12 + len(body)) + body


doc, data = model()
write_json(os.path.join(here, "hierarchy.gltf"), doc)
with open(os.path.join(here, "hierarchy.glb"), "wb") as f:
    f.write(glb(doc, data))
with open(os.path.join(bad, "gltf_truncated.glb"), "wb") as f:
    f.write(glb(doc, data)[:300])
write_json(os.path.join(bad, "gltf_missing_buffer.gltf"), model(buffer_uri="missing.bin")[0])
write_json(os.path.join(bad, "gltf_accessor_out_of_range.gltf"), model(count_override=400)[0])
write_json(os.path.join(bad, "gltf_node_cycle.gltf"), model(cycle=True)[0])
write_json(os.path.join(bad, "gltf_required_extension.gltf"), model(required="KHR_draco_mesh_compression")[0])
broken = model()[0]
broken["accessors"][4]["bufferView"] = 1  # the tetrahedron's indices read from the normals: 0.0 and 1.0 as uint16
broken["accessors"][4]["componentType"] = 5125  # as uint32: huge indices
broken["accessors"][4]["count"] = 12
write_json(os.path.join(bad, "gltf_index_out_of_range.gltf"), broken)

# KHR_lights_punctual: a point light 10 from the origin at intensity 100 (1 at the middle
# of the mesh, roughly), a directional one of 2 lux, and a spot light (lit as a point).
lit = model()[0]
lit["extensionsUsed"] = ["KHR_lights_punctual", "EXT_unknown_for_the_test"]
lit["extensions"] = {"KHR_lights_punctual": {"lights": [
    {"type": "point", "intensity": 100, "color": [1, 0.5, 0.25]},
    {"type": "directional", "intensity": 2},
    {"type": "spot", "intensity": 50, "spot": {"outerConeAngle": 0.5}}]}}
lit["nodes"] += [
    {"name": "point", "translation": [0, 10, 0], "extensions": {"KHR_lights_punctual": {"light": 0}}},
    {"name": "sun", "rotation": [-0.7071068, 0, 0, 0.7071068], "extensions": {"KHR_lights_punctual": {"light": 1}}},
    {"name": "spot", "translation": [0, 0, 10], "extensions": {"KHR_lights_punctual": {"light": 2}}}]
lit["scenes"][0]["nodes"] += [3, 4, 5]
write_json(os.path.join(here, "lights.gltf"), lit)

# A base colour texture whose image is not an image.
textured = model()[0]
textured["images"] = [{"uri": "data:image/png;base64," + base64.b64encode(b"\x89PNG\r\n\x1a\nnot really").decode()}]
textured["textures"] = [{"source": 0}]
textured["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {"index": 0}
write_json(os.path.join(bad, "gltf_bad_image.gltf"), textured)

# Vertex colours (COLOR_0) on the square.
write_json(os.path.join(here, "colours.gltf"), model(colours=True)[0])
