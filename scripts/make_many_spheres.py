#!/usr/bin/env python3
"""Writes assets/scenes/many_spheres.json: a field of spheres for the BVH and item-buffer work.

Deterministic (fixed seed), so the committed file can be regenerated exactly:
    python3 scripts/make_many_spheres.py > assets/scenes/many_spheres.json
"""
import json
import random

rng = random.Random(1984)  # Weghorst, Hooper & Greenberg's year
palette = {
    "red": [0.85, 0.2, 0.15], "orange": [0.9, 0.5, 0.1], "yellow": [0.9, 0.8, 0.2],
    "green": [0.2, 0.7, 0.3], "teal": [0.1, 0.6, 0.6], "blue": [0.2, 0.35, 0.85],
    "violet": [0.55, 0.25, 0.75], "white": [0.85, 0.85, 0.85],
}
materials = {name: {"ka": [c * 0.3 for c in rgb], "kd": rgb, "ks": 0.4, "shininess": 40}
             for name, rgb in palette.items()}
materials["ground"] = {"ka": 0.3, "kd": 0.6, "ks": 0.0,
                       "checker": {"colors": [0.9, 0.55], "scale": 2.0}}
names = sorted(palette)
objects = [{"name": "ground", "type": "plane", "normal": [0, 1, 0], "offset": 0, "material": "ground"}]
n = 40  # 40 x 40 = 1600 spheres
for i in range(n):
    for j in range(n):
        r = rng.uniform(0.15, 0.35)
        x = (i - n / 2 + 0.5) * 1.0 + rng.uniform(-0.2, 0.2)
        z = (j - n / 2 + 0.5) * 1.0 + rng.uniform(-0.2, 0.2)
        material = rng.choice(names + ["mirror"] if rng.random() < 0.1 else names)
        objects.append({"type": "sphere", "center": [round(x, 3), round(r, 3), round(z, 3)],
                        "radius": round(r, 3), "material": material})
scene = {
    "camera": {"eye": [0, 9, 24], "look_at": [0, 0, 0], "up": [0, 1, 0], "fov": 50},
    "resolution": [640, 360],
    "background": [0.6, 0.75, 0.95],
    "ambient": 0.25,
    "lights": [{"type": "directional", "direction": [-0.4, -1, -0.3], "color": 0.8},
               {"type": "point", "position": [0, 12, 10], "color": 0.3}],
    "materials": materials,
    "objects": objects,
}
print(json.dumps(scene, indent=1))
