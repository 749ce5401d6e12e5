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
import math
import os

import gltf_quads


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
    materials = [gltf_quads.material("light", emission=E) if name == "light"
                 else gltf_quads.material(name, rho=MATERIALS[name]) for name in material_names]
    quads = [(name, material_names.index(material), [[c / 1000.0 for c in v] for v in quad])
             for name, material, quad in QUADS]
    yfov = 2.0 * math.atan(0.0125 / 0.035)  # film 25 mm, focal length 35 mm
    camera_node = {"name": "camera", "translation": [0.278, 0.273, -0.8],
                   "rotation": [0.0, 1.0, 0.0, 0.0]}  # glTF cameras look down -Z: turn to +Z
    camera = {"type": "perspective", "name": "Cornell camera",
              "perspective": {"yfov": round(yfov, 6), "aspectRatio": 1.0, "znear": 0.01}}
    out = os.path.join(os.path.dirname(os.path.abspath(__file__)), "cornell_box.gltf")
    gltf_quads.write_quad_scene(out, "Cornell box", "radview assets/make_cornell_box.py", materials, quads,
                                camera_node, camera)


if __name__ == "__main__":
    main()
