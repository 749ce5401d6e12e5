"""Writes a glTF scene of planar quads: the format radview's bundled scenes are written in.

Each quad is two triangles (glTF has no quads; radview merges coplanar pairs back on import),
vertices in metres, (v1-v0)x(v2-v0) facing the lit side. Materials are diffuse (baseColorFactor
is rho) or emitters (emissiveFactor x KHR_materials_emissive_strength is the exitance E).
"""
import base64
import json
import struct


def material(name, rho=None, emission=None):
    """A glTF material: rho (RGB) for a reflector, emission E (RGB exitance) for an emitter."""
    if emission is not None:
        peak = max(emission)
        return {
            "name": name,
            "pbrMetallicRoughness": {"baseColorFactor": [0.0, 0.0, 0.0, 1.0], "metallicFactor": 0.0},
            "emissiveFactor": [round(c / peak, 6) for c in emission],
            "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": round(peak, 6)}},
        }
    return {"name": name, "pbrMetallicRoughness": {"baseColorFactor": list(rho) + [1.0], "metallicFactor": 0.0}}


def write_quad_scene(path, title, generator, materials, quads, camera_node, camera):
    """quads: (name, material index, 4 vertices in metres). camera_node: a glTF node for the camera."""
    blob = bytearray()
    accessors, views, meshes, nodes = [], [], [], []
    for name, material_index, positions in quads:
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
            "material": material_index}]})
        nodes.append({"name": name, "mesh": len(meshes) - 1})
    nodes.append({"name": camera_node["name"], "camera": 0, **{k: v for k, v in camera_node.items() if k != "name"}})
    gltf = {
        "asset": {"version": "2.0", "generator": generator},
        "extensionsUsed": ["KHR_materials_emissive_strength"],
        "scene": 0,
        "scenes": [{"name": title, "nodes": list(range(len(nodes)))}],
        "nodes": nodes,
        "meshes": meshes,
        "materials": materials,
        "cameras": [camera],
        "accessors": accessors,
        "bufferViews": views,
        "buffers": [{"byteLength": len(blob),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(blob)).decode()}],
    }
    with open(path, "w") as f:
        json.dump(gltf, f, indent=1)
        f.write("\n")
    print(path)
