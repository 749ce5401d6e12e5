#!/usr/bin/env python3
"""Writes cornell_box.gltf from the published Cornell box data (../shared/corpus/cornell-box-data.md).

The numbers below are the measured geometry (mm, converted to metres as glTF requires) and
RGB stand-ins for the measured spectra: each channel is the mean of the spectrum over a
third of 400-700 nm (R 600-700, G 500-596, B 400-496 nm). Choices of ours, stated:
  * the light is lowered 0.1 mm below the ceiling (548.7 mm) so the two do not coincide;
  * every quad is written as two triangles (glTF has no quads); radview merges coplanar
    pairs back into quads on import. The red wall is not planar (v3 is 3 mm off the plane
    of v0 v1 v2) and so stays two triangles;
  * emission E (exitance, the unit of radiosity B) = pi * L, with L the band means of the
    light spectrum usually used for this scene (400:0, 500:8, 600:15.6, 700:18.4).
Run: python3 assets/make_cornell_box.py  (writes assets/cornell_box.gltf)
"""
import base64
import json
import math
import os
import struct


def band_mean(samples, lo, hi, step=4):
    """Mean of a piecewise-linear spectrum sampled at lo, lo+step, ..., <= hi."""
    xs = sorted(samples)
    def at(w):
        for a, b in zip(xs, xs[1:]):
            if a <= w <= b:
                t = (w - a) / (b - a)
                return samples[a] * (1 - t) + samples[b] * t
        raise ValueError(w)
    ws = range(lo, hi + 1, step)
    return sum(at(w) for w in ws) / len(ws)


LIGHT_SPECTRUM = {400: 0.0, 500: 8.0, 600: 15.6, 700: 18.4}
L = [band_mean(LIGHT_SPECTRUM, 600, 700), band_mean(LIGHT_SPECTRUM, 500, 596),
     band_mean(LIGHT_SPECTRUM, 400, 496)]
E = [math.pi * c for c in L]

# RGB = band means (R 600-700, G 500-596, B 400-496 nm) of the measured reflectance spectra.
MATERIALS = {
    "white": [0.734, 0.736, 0.698],
    "green": [0.133, 0.351, 0.114],
    "red": [0.576, 0.083, 0.056],
}

LIGHT_Y = 548.7
QUADS = [  # (name, material, 4 vertices in mm); (v1-v0)x(v2-v0) faces the lit side
    ("floor", "white", [(552.8, 0, 0), (0, 0, 0), (0, 0, 559.2), (549.6, 0, 559.2)]),
    ("light", "light", [(343, LIGHT_Y, 227), (343, LIGHT_Y, 332), (213, LIGHT_Y, 332), (213, LIGHT_Y, 227)]),
    ("ceiling", "white", [(556, 548.8, 0), (556, 548.8, 559.2), (0, 548.8, 559.2), (0, 548.8, 0)]),
    ("back_wall", "white", [(549.6, 0, 559.2), (0, 0, 559.2), (0, 548.8, 559.2), (556, 548.8, 559.2)]),
    ("green_wall", "green", [(0, 0, 559.2), (0, 0, 0), (0, 548.8, 0), (0, 548.8, 559.2)]),
    ("red_wall", "red", [(552.8, 0, 0), (549.6, 0, 559.2), (556, 548.8, 559.2), (556, 548.8, 0)]),
    ("short_block_top", "white", [(130, 165, 65), (82, 165, 225), (240, 165, 272), (290, 165, 114)]),
    ("short_block_1", "white", [(290, 0, 114), (290, 165, 114), (240, 165, 272), (240, 0, 272)]),
    ("short_block_2", "white", [(130, 0, 65), (130, 165, 65), (290, 165, 114), (290, 0, 114)]),
    ("short_block_3", "white", [(82, 0, 225), (82, 165, 225), (130, 165, 65), (130, 0, 65)]),
    ("short_block_4", "white", [(240, 0, 272), (240, 165, 272), (82, 165, 225), (82, 0, 225)]),
    ("tall_block_top", "white", [(423, 330, 247), (265, 330, 296), (314, 330, 456), (472, 330, 406)]),
    ("tall_block_1", "white", [(423, 0, 247), (423, 330, 247), (472, 330, 406), (472, 0, 406)]),
    ("tall_block_2", "white", [(472, 0, 406), (472, 330, 406), (314, 330, 456), (314, 0, 456)]),
    ("tall_block_3", "white", [(314, 0, 456), (314, 330, 456), (265, 330, 296), (265, 0, 296)]),
    ("tall_block_4", "white", [(265, 0, 296), (265, 330, 296), (423, 330, 247), (423, 0, 247)]),
]


def main():
    material_names = ["white", "green", "red", "light"]
    materials = []
    for name in material_names:
        if name == "light":
            peak = max(E)
            materials.append({
                "name": "light",
                "pbrMetallicRoughness": {"baseColorFactor": [0.0, 0.0, 0.0, 1.0], "metallicFactor": 0.0},
                "emissiveFactor": [round(c / peak, 6) for c in E],
                "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": round(peak, 6)}},
            })
        else:
            materials.append({
                "name": name,
                "pbrMetallicRoughness": {"baseColorFactor": MATERIALS[name] + [1.0], "metallicFactor": 0.0},
            })

    blob = bytearray()
    accessors, views, meshes, nodes = [], [], [], []
    for name, material, quad in QUADS:
        positions = [[c / 1000.0 for c in v] for v in quad]
        offset = len(blob)
        for p in positions:
            blob += struct.pack("<3f", *p)
        views.append({"buffer": 0, "byteOffset": offset, "byteLength": 48, "target": 34962})
        accessors.append({
            "bufferView": len(views) - 1, "componentType": 5126, "count": 4, "type": "VEC3",
            "min": [min(p[i] for p in positions) for i in range(3)],
            "max": [max(p[i] for p in positions) for i in range(3)],
        })
        position_accessor = len(accessors) - 1
        offset = len(blob)
        blob += struct.pack("<6H", 0, 1, 2, 0, 2, 3)
        views.append({"buffer": 0, "byteOffset": offset, "byteLength": 12, "target": 34963})
        accessors.append({"bufferView": len(views) - 1, "componentType": 5123, "count": 6, "type": "SCALAR"})
        while len(blob) % 4:
            blob.append(0)
        meshes.append({"name": name, "primitives": [{
            "attributes": {"POSITION": position_accessor}, "indices": len(accessors) - 1,
            "material": material_names.index(material)}]})
        nodes.append({"name": name, "mesh": len(meshes) - 1})

    yfov = 2.0 * math.atan(0.0125 / 0.035)  # film 25 mm, focal length 35 mm
    nodes.append({"name": "camera", "camera": 0, "translation": [0.278, 0.273, -0.8],
                  "rotation": [0.0, 1.0, 0.0, 0.0]})  # glTF cameras look down -Z: turn to +Z

    gltf = {
        "asset": {"version": "2.0", "generator": "radview assets/make_cornell_box.py"},
        "extensionsUsed": ["KHR_materials_emissive_strength"],
        "scene": 0,
        "scenes": [{"name": "Cornell box", "nodes": list(range(len(nodes)))}],
        "nodes": nodes,
        "meshes": meshes,
        "materials": materials,
        "cameras": [{"type": "perspective", "name": "Cornell camera",
                     "perspective": {"yfov": round(yfov, 6), "aspectRatio": 1.0, "znear": 0.01}}],
        "accessors": accessors,
        "bufferViews": views,
        "buffers": [{"byteLength": len(blob),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(blob)).decode()}],
    }
    out = os.path.join(os.path.dirname(os.path.abspath(__file__)), "cornell_box.gltf")
    with open(out, "w") as f:
        json.dump(gltf, f, indent=1)
        f.write("\n")
    print(out)


if __name__ == "__main__":
    main()
