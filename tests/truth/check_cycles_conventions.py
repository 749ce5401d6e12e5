#!/usr/bin/python3
"""Checks cycles_reference.py against closed-form answers (numpy, OpenImageIO; runs blender).

  /usr/bin/python3 tests/truth/check_cycles_conventions.py [--spp 256] [--keep DIR]

1. furnace: a closed cube, faces wound inward, rho (0.5, 0.25, 0.75), E 1: every pixel of a
   view from inside must read B = E / (1 - rho) = (2, 1.333, 4) (the emission factor, RGB rho
   and the bounce limit);
2. under_emitter: a unit square emitter (E 1, facing down) at height 1 over a rho 0.5 floor,
   the floor point below its centre seen through a narrow camera from the side: B = rho E F,
   F = the closed-form point-to-parallel-square form factor (0.239466);
3. emitter_flipped: the same with the emitter facing up: 0 (emitters are one-sided);
4. emitter_back: the camera above the down-facing emitter, seeing its back: 0 (back faces black).
Exit status 0 when all hold (furnace and under_emitter within 4 standard errors and 1 %).
"""
import argparse
import base64
import json
import math
import os
import struct
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from surface_means import read_rgb  # noqa: E402


def write_gltf(path, quads, materials, eye, target, yfov):
    """quads: (material index, 4 corners, counter-clockwise seen from the front)."""
    blob, accessors, views, meshes, nodes = bytearray(), [], [], [], []
    for material, corners in quads:
        views.append({"buffer": 0, "byteOffset": len(blob), "byteLength": 48})
        for c in corners:
            blob += struct.pack("<3f", *c)
        accessors.append({"bufferView": len(views) - 1, "componentType": 5126, "count": 4, "type": "VEC3",
                          "min": [min(c[i] for c in corners) for i in range(3)],
                          "max": [max(c[i] for c in corners) for i in range(3)]})
        views.append({"buffer": 0, "byteOffset": len(blob), "byteLength": 12})
        blob += struct.pack("<6H", 0, 1, 2, 0, 2, 3)
        accessors.append({"bufferView": len(views) - 1, "componentType": 5123, "count": 6, "type": "SCALAR"})
        meshes.append({"primitives": [{"attributes": {"POSITION": len(accessors) - 2},
                                       "indices": len(accessors) - 1, "material": material}]})
        nodes.append({"mesh": len(meshes) - 1})
    # A camera node's matrix: columns right, up, -forward, eye.
    f = [t - e for t, e in zip(target, eye)]
    n = math.sqrt(sum(v * v for v in f))
    f = [v / n for v in f]
    up0 = [0.0, 1.0, 0.0] if abs(f[1]) < 0.99 else [0.0, 0.0, -1.0]
    r = [f[1] * up0[2] - f[2] * up0[1], f[2] * up0[0] - f[0] * up0[2], f[0] * up0[1] - f[1] * up0[0]]
    n = math.sqrt(sum(v * v for v in r))
    r = [v / n for v in r]
    u = [r[1] * f[2] - r[2] * f[1], r[2] * f[0] - r[0] * f[2], r[0] * f[1] - r[1] * f[0]]
    nodes.append({"camera": 0, "matrix": r + [0.0] + u + [0.0] + [-v for v in f] + [0.0] + list(eye) + [1.0]})
    mats = []
    for rho, E in materials:
        peak = max(E) if max(E) > 1 else 1.0
        m = {"pbrMetallicRoughness": {"baseColorFactor": list(rho) + [1.0], "metallicFactor": 0.0},
             "emissiveFactor": [c / peak for c in E]}
        if peak != 1.0:
            m["extensions"] = {"KHR_materials_emissive_strength": {"emissiveStrength": peak}}
        mats.append(m)
    gltf = {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": list(range(len(nodes)))}],
            "nodes": nodes, "meshes": meshes, "materials": mats,
            "cameras": [{"type": "perspective", "perspective": {"yfov": yfov, "znear": 0.001}}],
            "accessors": accessors, "bufferViews": views,
            "buffers": [{"byteLength": len(blob),
                         "uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(blob)).decode()}]}
    if any("extensions" in m for m in mats):
        gltf["extensionsUsed"] = ["KHR_materials_emissive_strength"]
    with open(path, "w") as f:
        json.dump(gltf, f)


def cube_inward(h):
    """The six faces of [-h, h]^3, counter-clockwise seen from inside."""
    faces = []
    for axis in range(3):
        for sign in (-1.0, 1.0):
            a, b = (axis + 1) % 3, (axis + 2) % 3
            quad = []
            for s, t in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
                p = [0.0, 0.0, 0.0]
                p[axis], p[a], p[b] = sign * h, s * h, t * h
                quad.append(p)
            # (a, b, axis) is right-handed, so this order faces +axis: inward on the -h face.
            faces.append(quad if sign < 0 else quad[::-1])
    return faces


def square_form_factor(a, h):
    """Point to a parallel a x a square centred above it at height h (four corner rectangles)."""
    x = y = (a / 2) / h
    corner = (x / math.sqrt(1 + x * x) * math.atan(y / math.sqrt(1 + x * x))
              + y / math.sqrt(1 + y * y) * math.atan(x / math.sqrt(1 + y * y))) / (2 * math.pi)
    return 4 * corner


def render(blender, gltf, out, size, spp, seed):
    start = time.time()
    cmd = [blender, "-b", "--factory-startup", "--python", os.path.join(HERE, "cycles_reference.py"), "--",
           gltf, out, "--size", size, "--spp", str(spp), "--seed", str(seed)]
    run = subprocess.run(cmd, capture_output=True, text=True)
    if run.returncode != 0 or not os.path.isfile(out):
        raise SystemExit("render failed: %s\n%s%s" % (" ".join(cmd), run.stdout[-2000:], run.stderr[-2000:]))
    return time.time() - start


def stats(values):
    n = len(values)
    mean = sum(values) / n
    sd = math.sqrt(sum((v - mean) ** 2 for v in values) / (n - 1)) if n > 1 else 0.0
    return mean, sd / math.sqrt(n), min(values), max(values)


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--spp", type=int, default=256)
    p.add_argument("--blender", default="blender")
    p.add_argument("--keep", help="directory to keep the scenes and images in")
    args = p.parse_args()
    work = args.keep or tempfile.mkdtemp(prefix="cycles_conventions_")
    os.makedirs(work, exist_ok=True)
    ok = True

    # 1. furnace
    rho = (0.5, 0.25, 0.75)
    scene = os.path.join(work, "furnace.gltf")
    write_gltf(scene, [(0, q) for q in cube_inward(1.0)], [(rho, (1.0, 1.0, 1.0))],
               eye=(0.3, -0.2, 0.1), target=(1.0, 0.4, 1.0), yfov=math.radians(100))
    out = os.path.join(work, "furnace.exr")
    seconds = render(args.blender, scene, out, "32x32", args.spp, 1)
    px = read_rgb(out).reshape(-1, 3)
    for c, name in enumerate("RGB"):
        expected = 1.0 / (1.0 - rho[c])
        mean, se, lo, hi = stats([v[c] for v in px])
        good = abs(mean - expected) <= max(4 * se, 0) + 0.01 * expected
        ok &= good
        print("furnace %s: mean %.5f (+- %.5f), pixels %.4f..%.4f, expected %.5f, %.2f %% %s  [%.1f s]"
              % (name, mean, se, lo, hi, expected, 100 * (mean / expected - 1), "ok" if good else "FAIL", seconds))

    # 2.-4. a unit square emitter over a floor
    floor = [(-20, 0, -20), (-20, 0, 20), (20, 0, 20), (20, 0, -20)]        # faces +Y
    light_down = [(-0.5, 1, -0.5), (0.5, 1, -0.5), (0.5, 1, 0.5), (-0.5, 1, 0.5)]  # faces -Y
    light_up = light_down[::-1]
    materials = [((0.5, 0.5, 0.5), (0.0, 0.0, 0.0)), ((0.0, 0.0, 0.0), (1.0, 1.0, 1.0))]
    expected = 0.5 * square_form_factor(1.0, 1.0)
    cases = [("under_emitter", light_down, (3.0, 0.6, 0.0), expected),
             ("emitter_flipped", light_up, (3.0, 0.6, 0.0), 0.0),
             ("emitter_back", light_down, (0.0, 3.0, 0.0), 0.0)]
    for name, light, eye, want in cases:
        scene = os.path.join(work, name + ".gltf")
        write_gltf(scene, [(0, floor), (1, light)], materials, eye=eye, target=(0.0, 0.0, 0.0), yfov=0.004)
        out = os.path.join(work, name + ".exr")
        seconds = render(args.blender, scene, out, "8x8", args.spp, 1)
        px = read_rgb(out).reshape(-1, 3)
        mean, se, lo, hi = stats([v[1] for v in px])
        good = (abs(mean - want) <= 4 * se + 0.01 * want) if want else hi == 0.0
        ok &= good
        print("%s: G mean %.6f (+- %.6f), pixels %.5f..%.5f, expected %.6f %s  [%.1f s]"
              % (name, mean, se, lo, hi, want, "ok" if good else "FAIL", seconds))
    print("all hold" if ok else "SOME CHECK FAILED", "(files in %s)" % work)
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
