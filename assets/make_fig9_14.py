#!/usr/bin/env python3
"""Writes fig9_14_scene.gltf: a scene like C&W fig. 9.14 (after Salesin, Lischinski, DeRose 1992).

A square area emitter over a square receiver, a square occluder between them, all three
parallel with parallel edges. The occluder's edges are parallel to the emitter's, so every
shadow boundary on the receiver is a D1 event (C0, a kink in B) and the umbra and penumbra
are squares whose boundaries meet at apexes, where B is C1 again (Salesin et al.). The
solution bundled as fig9_14.gltf is radview's discontinuity-meshed solve of it:

    radview solve assets/fig9_14_scene.gltf -o assets/fig9_14.gltf --discontinuity-meshing \\
        --element-size 0.35 --tolerance 255 --seed 1

Run: python3 assets/make_fig9_14.py  (writes assets/fig9_14_scene.gltf)
"""
import math
import os

import gltf_quads

MATERIALS = [gltf_quads.material("white", rho=[0.7, 0.7, 0.7]),
             gltf_quads.material("light", emission=[6.0, 6.0, 6.0])]
# The emitter is off to one side, so the shadow falls clear of the occluder in a view from above.
QUADS = [  # (name, material, vertices in metres), (v1-v0)x(v2-v0) facing the lit side
    ("receiver", 0, [(0, 0, 0), (1.4, 0, 0), (1.4, 1, 0), (0, 1, 0)]),
    ("occluder", 0, [(0.4, 0.4, 0.25), (0.6, 0.4, 0.25), (0.6, 0.6, 0.25), (0.4, 0.6, 0.25)]),
    ("emitter", 1, [(0.0, 0.38, 0.5), (0.0, 0.62, 0.5), (0.2, 0.62, 0.5), (0.2, 0.38, 0.5)]),
]


def main():
    # Straight above the receiver looking down (glTF cameras look down -Z, as this one does).
    camera_node = {"name": "camera", "translation": [0.7, 0.5, 1.6]}
    camera = {"type": "perspective", "name": "fig. 9.14 camera",
              "perspective": {"yfov": round(math.radians(45), 6), "aspectRatio": 1.0, "znear": 0.01}}
    out = os.path.join(os.path.dirname(os.path.abspath(__file__)), "fig9_14_scene.gltf")
    gltf_quads.write_quad_scene(out, "C&W fig. 9.14", "radview assets/make_fig9_14.py", MATERIALS, QUADS,
                                camera_node, camera)


if __name__ == "__main__":
    main()
