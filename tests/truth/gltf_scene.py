"""A glTF scene read the way radview's importer reads it (renderer/scene/gltf_import.cpp), with
its own parser (exact: no Y-up -> Z-up conversion, no vertex merging), for the Cycles reference
(cycles_reference.py, which runs inside Blender and imports this beside it): triangles in world
space with their rho, E and surface, and the camera. Pure Python: no bpy.
"""
import base64
import json
import math
import os
import struct
import urllib.parse


class SceneError(Exception):
    """A problem with the input file: reported as 'PATH: problem'."""


# ---------------------------------------------------------------------------------------------
# glTF reading (the parts radview's importer reads)

COMPONENTS = {5120: ("b", 1, 127.0), 5121: ("B", 1, 255.0), 5122: ("h", 2, 32767.0),
              5123: ("H", 2, 65535.0), 5125: ("I", 4, None), 5126: ("f", 4, None)}
TYPE_SIZE = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4, "MAT2": 4, "MAT3": 9, "MAT4": 16}


def load_gltf(path):
    if not os.path.isfile(path):
        raise SceneError("no such file")
    with open(path, "rb") as f:
        data = f.read()
    bin_chunk = None
    if data[:4] == b"glTF":
        _magic, version, length = struct.unpack_from("<4sII", data, 0)
        if version != 2:
            raise SceneError("GLB version %d (radview reads glTF 2.0)" % version)
        offset, doc = 12, None
        while offset + 8 <= min(length, len(data)):
            chunk_length, chunk_type = struct.unpack_from("<II", data, offset)
            chunk = data[offset + 8:offset + 8 + chunk_length]
            if chunk_type == 0x4E4F534A and doc is None:
                doc = json.loads(chunk.decode("utf-8"))
            elif chunk_type == 0x004E4942 and bin_chunk is None:
                bin_chunk = chunk
            offset += 8 + chunk_length
        if doc is None:
            raise SceneError("GLB without a JSON chunk")
    else:
        try:
            doc = json.loads(data.decode("utf-8"))
        except (UnicodeDecodeError, json.JSONDecodeError) as e:
            raise SceneError("not glTF JSON (%s)" % e)
    buffers = []
    for i, b in enumerate(doc.get("buffers", [])):
        uri = b.get("uri")
        if uri is None:
            if i != 0 or bin_chunk is None:
                raise SceneError("buffer %d has no uri and no GLB BIN chunk" % i)
            buffers.append(bin_chunk)
        elif uri.startswith("data:"):
            buffers.append(base64.b64decode(uri.split(",", 1)[1]))
        else:
            file = os.path.join(os.path.dirname(path), urllib.parse.unquote(uri))
            if not os.path.isfile(file):
                raise SceneError("buffer %d: %s does not exist" % (i, file))
            with open(file, "rb") as f:
                buffers.append(f.read())
    return doc, buffers


def read_accessor(doc, buffers, index, what):
    """Flat list of the accessor's values (normalized integers decoded as glTF says), and its width."""
    try:
        a = doc["accessors"][index]
        fmt, size, scale = COMPONENTS[a["componentType"]]
        n, count = TYPE_SIZE[a["type"]], a["count"]
        normalized = a.get("normalized", False)

        def unpack(buffer, start, stride, elements):
            if stride in (0, n * size):
                return list(struct.unpack_from("<%d%s" % (elements * n, fmt), buffer, start))
            out = []
            for i in range(elements):
                out.extend(struct.unpack_from("<%d%s" % (n, fmt), buffer, start + i * stride))
            return out

        if "bufferView" in a:
            view = doc["bufferViews"][a["bufferView"]]
            values = unpack(buffers[view["buffer"]], view.get("byteOffset", 0) + a.get("byteOffset", 0),
                            view.get("byteStride", 0), count)
        else:
            values = [0] * (count * n)
        sparse = a.get("sparse")
        if sparse:
            ifmt, isize, _ = COMPONENTS[sparse["indices"]["componentType"]]
            iview = doc["bufferViews"][sparse["indices"]["bufferView"]]
            vview = doc["bufferViews"][sparse["values"]["bufferView"]]
            targets = struct.unpack_from("<%d%s" % (sparse["count"], ifmt), buffers[iview["buffer"]],
                                         iview.get("byteOffset", 0) + sparse["indices"].get("byteOffset", 0))
            replacement = unpack(buffers[vview["buffer"]],
                                 vview.get("byteOffset", 0) + sparse["values"].get("byteOffset", 0), 0,
                                 sparse["count"])
            for k, t in enumerate(targets):
                values[t * n:(t + 1) * n] = replacement[k * n:(k + 1) * n]
    except (KeyError, IndexError, TypeError, struct.error) as e:
        raise SceneError("%s: accessor %s cannot be read (%s: %s)" % (what, index, type(e).__name__, e))
    if normalized and scale is not None:
        signed = fmt in "bh"
        values = [max(v / scale, -1.0) if signed else v / scale for v in values]
    return [float(v) for v in values], n


def mat_mul(a, b):  # 4x4, row-major nested lists
    return [[sum(a[i][k] * b[k][j] for k in range(4)) for j in range(4)] for i in range(4)]


def local_transform(node):
    if "matrix" in node:  # column-major
        m = node["matrix"]
        return [[m[c * 4 + r] for c in range(4)] for r in range(4)]
    t = node.get("translation", [0.0, 0.0, 0.0])
    x, y, z, w = node.get("rotation", [0.0, 0.0, 0.0, 1.0])
    s = node.get("scale", [1.0, 1.0, 1.0])
    q = math.sqrt(x * x + y * y + z * z + w * w)
    if not q > 0.0:
        raise SceneError("node %s: rotation is not a usable quaternion" % node.get("name", "?"))
    x, y, z, w = x / q, y / q, z / q, w / q
    r = [[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
         [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
         [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]]
    return [[r[i][0] * s[0], r[i][1] * s[1], r[i][2] * s[2], t[i]] for i in range(3)] + [[0.0, 0.0, 0.0, 1.0]]


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def normalize(a):
    length = math.sqrt(dot(a, a))
    return (a[0] / length, a[1] / length, a[2] / length)


def clamp01(values):
    return tuple(min(max(float(v), 0.0), 1.0) for v in values)


class Scene:
    def __init__(self, path):
        self.doc, self.buffers = load_gltf(path)
        doc = self.doc
        self.solution = "RADVIEW_radiosity_mesh" in doc.get("extensions", {})
        self.surfaces = []    # (label, [(p0, p1, p2, (rho, E))]) per (node, primitive)
        self.camera = None    # (eye, forward, up, yfov)
        self.materials = {}
        nodes = doc.get("nodes", [])
        parent = [-1] * len(nodes)
        for n, node in enumerate(nodes):
            for c in node.get("children", []):
                parent[c] = n
        if "scene" in doc:  # radview: the default scene, else every root node (gltf_import.cpp)
            roots = doc["scenes"][doc["scene"]].get("nodes", [])
        else:
            roots = [n for n in range(len(nodes)) if parent[n] == -1]
        identity = [[float(i == j) for j in range(4)] for i in range(4)]
        for root in roots:
            stack = [(root, identity)]
            while stack:
                n, world_from_parent = stack.pop()
                node = nodes[n]
                world = mat_mul(world_from_parent, local_transform(node))
                if "mesh" in node:
                    self.add_mesh(n, node, world)
                if "camera" in node and self.camera is None:
                    self.add_camera(node, world)
                for child in reversed(node.get("children", [])):
                    stack.append((child, world))

    def material(self, index):
        if index in self.materials:
            return self.materials[index]
        if index is None:
            rho, E = (1.0, 1.0, 1.0), (0.0, 0.0, 0.0)
        else:
            m = self.doc["materials"][index]
            if self.solution:
                ext = m["extensions"]["RADVIEW_radiosity_mesh"]
                rho, E = tuple(map(float, ext["rho"])), tuple(map(float, ext["E"]))
            else:
                rho = clamp01(m.get("pbrMetallicRoughness", {}).get("baseColorFactor", [1, 1, 1, 1])[:3])
                strength = m.get("extensions", {}).get("KHR_materials_emissive_strength", {}).get(
                    "emissiveStrength", 1.0)
                E = tuple(c * float(strength) for c in clamp01(m.get("emissiveFactor", [0, 0, 0])))
        self.materials[index] = (rho, E)
        return rho, E

    def add_mesh(self, n, node, world):
        mesh = self.doc["meshes"][node["mesh"]]
        linear = [row[:3] for row in world[:3]]
        det = (linear[0][0] * (linear[1][1] * linear[2][2] - linear[1][2] * linear[2][1])
               - linear[0][1] * (linear[1][0] * linear[2][2] - linear[1][2] * linear[2][0])
               + linear[0][2] * (linear[1][0] * linear[2][1] - linear[1][1] * linear[2][0]))
        mirrored = det < 0.0
        for p, prim in enumerate(mesh.get("primitives", [])):
            what = "mesh %d primitive %d" % (node["mesh"], p)
            mode = prim.get("mode", 4)
            if mode not in (4, 5, 6) or "POSITION" not in prim.get("attributes", {}):
                continue
            flat, _ = read_accessor(self.doc, self.buffers, prim["attributes"]["POSITION"], what + " POSITION")
            positions = []
            for i in range(0, len(flat), 3):
                x, y, z = flat[i:i + 3]
                positions.append(tuple(world[r][0] * x + world[r][1] * y + world[r][2] * z + world[r][3]
                                       for r in range(3)))
            if "indices" in prim:
                indices = [int(v) for v in read_accessor(self.doc, self.buffers, prim["indices"], what + " indices")[0]]
            else:
                indices = list(range(len(positions)))
            base = self.material(prim.get("material"))
            colours = None
            if "COLOR_0" in prim["attributes"] and not self.solution:
                values, width = read_accessor(self.doc, self.buffers, prim["attributes"]["COLOR_0"], what + " COLOR_0")
                colours = [values[i:i + 3] for i in range(0, len(values), width)]
            if mode == 4:
                corners = [(indices[i], indices[i + 1], indices[i + 2]) for i in range(0, len(indices) - 2, 3)]
            elif mode == 5:
                corners = [(indices[i], indices[i + 1 + i % 2], indices[i + 2 - i % 2]) for i in range(len(indices) - 2)]
            else:
                corners = [(indices[i + 1], indices[i + 2], indices[0]) for i in range(len(indices) - 2)]
            triangles = []
            for a, b, c in corners:
                if mirrored:
                    b, c = c, b
                pa, pb, pc = positions[a], positions[b], positions[c]
                longest2 = max(dot(sub(pb, pa), sub(pb, pa)), dot(sub(pc, pa), sub(pc, pa)), dot(sub(pc, pb), sub(pc, pb)))
                area2 = cross(sub(pb, pa), sub(pc, pa))
                if not math.sqrt(dot(area2, area2)) > 1e-10 * longest2:
                    continue  # radview drops degenerate triangles
                material = base
                if colours is not None:  # gltf_import.cpp modulatedMaterial: the corners' mean, 8-bit steps
                    mean = [(colours[a][k] + colours[b][k] + colours[c][k]) / 3.0 for k in range(3)]
                    step = [round(min(max(v, 0.0), 1.0) * 255.0) / 255.0 for v in mean]
                    material = (tuple(base[0][k] * step[k] for k in range(3)), base[1])
                triangles.append((pa, pb, pc, material))
            label = "node %d (%s) mesh %d (%s) primitive %d" % (n, node.get("name", ""), node["mesh"],
                                                                mesh.get("name", ""), p)
            self.surfaces.append((label, triangles))

    def add_camera(self, node, world):
        camera = self.doc["cameras"][node["camera"]]
        if camera.get("type") != "perspective":
            return  # radview ignores orthographic cameras
        yfov = float(camera["perspective"]["yfov"])
        if not 0.0 < yfov < math.pi:
            raise SceneError("camera %d: yfov %g is not in (0, pi)" % (node["camera"], yfov))
        linear = [row[:3] for row in world[:3]]
        eye = (world[0][3], world[1][3], world[2][3])
        forward = normalize(tuple(-linear[r][2] for r in range(3)))
        up = tuple(linear[r][1] for r in range(3))
        up = normalize(sub(up, tuple(dot(up, forward) * f for f in forward)))
        self.camera = (eye, forward, up, yfov)


# ---------------------------------------------------------------------------------------------
# Blender scene
