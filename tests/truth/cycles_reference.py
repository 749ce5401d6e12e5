"""A Cycles path-traced reference for a glTF scene, under radview's scene conventions.

Run:
  blender -b --factory-startup --python tests/truth/cycles_reference.py -- \
      SCENE.gltf OUT.exr --size 64x64 --spp 1024 --seed 1 [--threads N] [--ids IDS.exr]

Writes OUT.exr: float32 RGBA OpenEXR (ZIP), scene-linear radiosity B per pixel, rows top first
(the EXR's first scanline is the image's top row, as radview's --linear-out), alpha 1.

The scene is read the way radview's importer reads it (renderer/scene/gltf_import.cpp), with
its own glTF parser, gltf_scene.py (exact: no Y-up -> Z-up conversion, no vertex merging):
  * the default scene's root nodes, or every parentless node when the file names no scene;
    node transforms (matrix, or T * R * S) composed in double precision, applied to POSITION;
  * TRIANGLES / TRIANGLE_STRIP / TRIANGLE_FAN in glTF's vertex order; points and lines skipped;
    a mirroring transform swaps two corners, so the front stays the side the winding faces;
    NORMAL is ignored (the normal is (v1 - v0) x (v2 - v0)); zero-area triangles dropped;
  * rho = baseColorFactor.rgb clamped to [0, 1], linear; E = clamp(emissiveFactor, 0, 1) x
    KHR_materials_emissive_strength.emissiveStrength (an exitance, the unit of B); no material
    means rho 1, E 0; COLOR_0 multiplies rho per triangle by its corners' mean, in 8-bit steps;
  * a radview solution file (root extension RADVIEW_radiosity_mesh) is rendered as a scene too:
    rho and E from each material's RADVIEW_radiosity_mesh extension, COLOR_0 (B) ignored;
  * the camera: the first perspective camera in traversal order, looking down its node's -Z,
    up its +Y made orthogonal; yfov is the vertical field, the aspect is --size's (the file's
    aspectRatio ignored, as radview's render does).

Shading, per surface (the solver's one-sided model, renderer/gather/final_gather.h):
  * front side (the ray meets the face against its normal): Lambertian rho plus emission E,
    with Cycles' Emission strength E: Cycles' radiance for emission strength S, viewed, reads S
    in the image, and a Lambertian surface under it reads rho x (1/pi) integral S cos, so every
    pixel value is a radiosity B = pi L (checked by tests/truth/check_cycles_conventions.py);
  * back side: black and opaque (no emission, no reflection; rays stop there). An eye ray that
    sees a back face therefore reads 0, where radview shows the front's B^ (final_gather.h);
    compare such pixels only with care (--ids marks them with a negative id).

Render: Cycles, CPU, --spp samples, no adaptive sampling, no denoising, no clamping, 1024
diffuse / 1024 total bounces (Russian roulette as Cycles does it, unbiased), no glossy or
transmission, light threshold 0, one-pixel box filter, black world (not sampled), film opaque,
view transform Standard / look None / exposure 0 / gamma 1 (the EXR is scene-linear anyway).

--ids IDS.exr also writes, from one ray through each pixel's centre, the surface it meets:
k + 1 for the front of the k-th (node, primitive) in traversal order, -(k + 1) for its back, 0
for none (every channel the same), with IDS.exr.json naming each k.
"""
import argparse
import json
import math
import os
import sys
import time

import bpy

PROGRAM = "cycles_reference.py"


# The glTF reading, radview's way, is in gltf_scene.py beside this script (Blender runs this
# file alone, so its folder goes on the path first).
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gltf_scene import Scene, SceneError, cross, dot, normalize, sub  # noqa: E402


def shader_for(rho, E, cache):
    key = (rho, E)
    if key in cache:
        return cache[key]
    m = bpy.data.materials.new("rho %.6g %.6g %.6g E %.6g %.6g %.6g" % (*rho, *E))
    m.use_nodes = True
    nt = m.node_tree
    nt.nodes.clear()
    out = nt.nodes.new("ShaderNodeOutputMaterial")
    diffuse = nt.nodes.new("ShaderNodeBsdfDiffuse")
    diffuse.inputs["Color"].default_value = (*rho, 1.0)
    diffuse.inputs["Roughness"].default_value = 0.0  # Lambert (Oren-Nayar above 0)
    front = diffuse
    if max(E) > 0.0:
        emission = nt.nodes.new("ShaderNodeEmission")
        emission.inputs["Color"].default_value = (*E, 1.0)
        emission.inputs["Strength"].default_value = 1.0
        add = nt.nodes.new("ShaderNodeAddShader")
        nt.links.new(diffuse.outputs[0], add.inputs[0])
        nt.links.new(emission.outputs[0], add.inputs[1])
        front = add
    back = nt.nodes.new("ShaderNodeBsdfDiffuse")  # black: no closure, the path ends here
    back.inputs["Color"].default_value = (0.0, 0.0, 0.0, 1.0)
    geometry = nt.nodes.new("ShaderNodeNewGeometry")
    mix = nt.nodes.new("ShaderNodeMixShader")
    nt.links.new(geometry.outputs["Backfacing"], mix.inputs["Fac"])
    nt.links.new(front.outputs[0], mix.inputs[1])
    nt.links.new(back.outputs[0], mix.inputs[2])
    nt.links.new(mix.outputs[0], out.inputs["Surface"])
    m.cycles.sample_as_light = max(E) > 0.0
    cache[key] = m
    return m


def build(scene_data, width, height):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    cache, objects = {}, []
    for k, (label, triangles) in enumerate(scene_data.surfaces):
        if not triangles:
            continue
        mesh = bpy.data.meshes.new("surface %d" % k)
        coords = [c for t in triangles for p in t[:3] for c in p]
        mesh.vertices.add(len(triangles) * 3)
        mesh.vertices.foreach_set("co", coords)
        mesh.loops.add(len(triangles) * 3)
        mesh.loops.foreach_set("vertex_index", list(range(len(triangles) * 3)))
        mesh.polygons.add(len(triangles))
        mesh.polygons.foreach_set("loop_start", list(range(0, len(triangles) * 3, 3)))
        mesh.polygons.foreach_set("loop_total", [3] * len(triangles))
        slots = {}
        for t in triangles:
            if t[3] not in slots:
                slots[t[3]] = len(slots)
                mesh.materials.append(shader_for(t[3][0], t[3][1], cache))
        mesh.polygons.foreach_set("material_index", [slots[t[3]] for t in triangles])
        mesh.polygons.foreach_set("use_smooth", [False] * len(triangles))
        mesh.update(calc_edges=True)
        obj = bpy.data.objects.new("surface %d" % k, mesh)
        obj["radview_surface"] = k
        scene.collection.objects.link(obj)
        objects.append(obj)

    eye, forward, up, yfov = scene_data.camera
    cam = bpy.data.cameras.new("camera")
    cam.type = "PERSP"
    cam.sensor_fit = "VERTICAL"
    cam.sensor_height = 24.0
    cam.lens = 0.5 * cam.sensor_height / math.tan(0.5 * yfov)
    cam.shift_x = cam.shift_y = 0.0
    bounds = [c for t in (tt for _, ts in scene_data.surfaces for tt in ts) for p in t[:3] for c in sub(p, eye)]
    far = 2.0 * math.sqrt(max(dot(bounds[i:i + 3], bounds[i:i + 3]) for i in range(0, len(bounds), 3)))
    cam.clip_start, cam.clip_end = 1e-6 * far, far
    camera = bpy.data.objects.new("camera", cam)
    right = cross(forward, up)
    import mathutils
    camera.matrix_world = mathutils.Matrix(((right[0], up[0], -forward[0], eye[0]),
                                            (right[1], up[1], -forward[1], eye[1]),
                                            (right[2], up[2], -forward[2], eye[2]),
                                            (0.0, 0.0, 0.0, 1.0)))
    scene.collection.objects.link(camera)
    scene.camera = camera

    world = bpy.data.worlds.new("black")
    world.use_nodes = True
    world.node_tree.nodes["Background"].inputs["Color"].default_value = (0.0, 0.0, 0.0, 1.0)
    world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.0
    world.cycles.sampling_method = "NONE"
    scene.world = world

    r = scene.render
    r.engine = "CYCLES"
    r.resolution_x, r.resolution_y, r.resolution_percentage = width, height, 100
    r.pixel_aspect_x = r.pixel_aspect_y = 1.0
    r.use_border = False
    r.film_transparent = False
    r.use_compositing = False
    r.use_sequencer = False
    r.use_persistent_data = False
    r.image_settings.file_format = "OPEN_EXR"
    r.image_settings.color_depth = "32"
    r.image_settings.color_mode = "RGBA"
    r.image_settings.exr_codec = "ZIP"
    v = scene.view_settings
    v.view_transform, v.look, v.exposure, v.gamma = "Standard", "None", 0.0, 1.0
    v.use_curve_mapping = False
    scene.display_settings.display_device = "sRGB"
    return scene, objects


def configure(scene, args):
    c = scene.cycles
    c.device = "CPU"
    c.samples = args.spp
    c.use_adaptive_sampling = False
    c.use_denoising = False
    c.use_preview_denoising = False
    c.seed = args.seed
    c.use_animated_seed = False
    c.sample_clamp_direct = 0.0
    c.sample_clamp_indirect = 0.0
    c.max_bounces = 1024
    c.diffuse_bounces = 1024
    c.glossy_bounces = 0
    c.transmission_bounces = 0
    c.volume_bounces = 0
    c.transparent_max_bounces = 0
    c.min_light_bounces = 0
    c.light_sampling_threshold = 0.0
    c.caustics_reflective = c.caustics_refractive = False
    c.blur_glossy = 0.0
    c.pixel_filter_type = "BOX"
    c.filter_width = 1.0
    c.film_exposure = 1.0
    c.time_limit = 0.0
    scene.render.threads_mode = "AUTO" if args.threads == 0 else "FIXED"
    if args.threads:
        scene.render.threads = args.threads


def write_ids(scene, objects, scene_data, args):
    """Surface id per pixel centre (ray cast), rows top first in the file, and a JSON legend."""
    width, height = args.width, args.height
    eye, forward, up, yfov = scene_data.camera
    right = cross(forward, up)
    half_h = math.tan(0.5 * yfov)
    half_w = half_h * width / height
    depsgraph = bpy.context.evaluated_depsgraph_get()
    ids = [0.0] * (width * height)
    import mathutils
    for j in range(height):
        y = (1.0 - 2.0 * (j + 0.5) / height) * half_h
        for i in range(width):
            x = (2.0 * (i + 0.5) / width - 1.0) * half_w
            d = normalize(tuple(forward[k] + x * right[k] + y * up[k] for k in range(3)))
            hit, _loc, normal, _face, obj, _m = scene.ray_cast(depsgraph, mathutils.Vector(eye), mathutils.Vector(d))
            if hit:
                k = obj.original["radview_surface"] + 1
                ids[j * width + i] = float(-k if dot(normal, d) > 0.0 else k)
    image = bpy.data.images.new("ids", width, height, alpha=True, float_buffer=True)
    pixels = []
    for j in reversed(range(height)):  # Blender images are bottom row first
        for i in range(width):
            v = ids[j * width + i]
            pixels += [v, v, v, 1.0]
    image.pixels = pixels
    image.filepath_raw = args.ids
    image.file_format = "OPEN_EXR"
    scene.render.image_settings.file_format = "OPEN_EXR"
    image.save_render(args.ids, scene=scene)
    with open(args.ids + ".json", "w") as f:
        json.dump({"scene": args.scene, "ids": {str(k + 1): label for k, (label, _) in enumerate(scene_data.surfaces)},
                   "rule": "k+1: front of surface k at the pixel centre, -(k+1): its back, 0: nothing"}, f, indent=1)


def parse_args(argv):
    p = argparse.ArgumentParser(prog=PROGRAM, description="Cycles reference of a glTF scene under radview's conventions")
    p.add_argument("scene")
    p.add_argument("out")
    p.add_argument("--size", default="64x64")
    p.add_argument("--spp", type=int, default=1024)
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--threads", type=int, default=0, help="render threads, 0 = all")
    p.add_argument("--ids", help="also write the per-pixel surface id image (EXR) and IDS.exr.json")
    args = p.parse_args(argv)
    try:
        args.width, args.height = (int(v) for v in args.size.lower().split("x"))
        assert args.width > 0 and args.height > 0
    except (ValueError, AssertionError):
        p.error("--size %r: expected WIDTHxHEIGHT" % args.size)
    if args.spp < 1 or args.threads < 0:
        p.error("--spp must be >= 1 and --threads >= 0")
    args.out = os.path.abspath(args.out)
    if args.ids:
        args.ids = os.path.abspath(args.ids)
    return args


def main():
    argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    args = parse_args(argv)
    try:
        scene_data = Scene(args.scene)
        if scene_data.camera is None:
            raise SceneError("no perspective camera (the reference renders from the file's camera)")
        if not any(t for _, t in scene_data.surfaces):
            raise SceneError("no triangles to render")
        if not any(max(t[3][1]) > 0.0 for _, ts in scene_data.surfaces for t in ts):
            raise SceneError("no material emits: the image would be black")
    except SceneError as e:
        print("%s: error: %s: %s" % (PROGRAM, args.scene, e), file=sys.stderr)
        sys.exit(1)
    except (KeyError, IndexError, TypeError, ValueError) as e:
        print("%s: error: %s: malformed glTF (%s: %s)" % (PROGRAM, args.scene, type(e).__name__, e), file=sys.stderr)
        sys.exit(1)
    scene, objects = build(scene_data, args.width, args.height)
    configure(scene, args)
    start = time.time()
    bpy.ops.render.render(write_still=False)
    seconds = time.time() - start
    os.makedirs(os.path.dirname(args.out), exist_ok=True)
    bpy.data.images["Render Result"].save_render(args.out, scene=scene)
    if not os.path.isfile(args.out):
        print("%s: error: %s: not written" % (PROGRAM, args.out), file=sys.stderr)
        sys.exit(1)
    print("%s: %s -> %s: %dx%d, %d spp, seed %d, %d triangles, %.1f s render" % (
        PROGRAM, args.scene, args.out, args.width, args.height, args.spp, args.seed,
        sum(len(t) for _, t in scene_data.surfaces), seconds))
    if args.ids:
        write_ids(scene, objects, scene_data, args)
        print("%s: ids -> %s (+ .json)" % (PROGRAM, args.ids))


if __name__ == "__main__":
    main()
