# Writes skinned_bar.gltf and morph_quad.gltf (run in this directory; the outputs are committed).
#
# skinned_bar.gltf: a bar 0.2 x 2 x 0.2 m standing on +Y from the origin, skinned to two joints
# (the root at the origin, the bend joint at y = 1 m). Rings every 0.25 m; below y = 0.75 only the
# root moves a vertex, above y = 1.25 only the bend joint, between them the weight goes linearly.
# The root's weight is in WEIGHTS_0 and the bend joint's in WEIGHTS_1 (8 influences a vertex), so
# a reader that ignores the second set does not bend it. Animation 0 "bend" turns the bend joint
# from no rotation (t = 0) to 90 degrees about +Z (t = 1, LINEAR): the top half then points to -X.
# Animation 1 "lift" moves the root up 0.5 m at t = 1 (STEP). A static ground quad at y = -0.05.
#
# morph_quad.gltf: a unit quad in the XY plane facing +Z with two morph targets: target 0 moves
# the top edge up 1 m, target 1 moves the right edge 0.5 m to +X. Mesh default weights (0.25, 0);
# animation "grow" (LINEAR) goes from weights (0, 0) at t = 0 to (1, 0.5) at t = 1.
import base64, json, math, struct


class Builder:
    def __init__(self):
        self.buf = b""
        self.views = []
        self.accessors = []

    def add(self, fmt, values, ctype, atype, count, target=None, minmax=False, stride_pack=None):
        while len(self.buf) % 4:
            self.buf += b"\0"
        data = struct.pack("<%d%s" % (len(values), fmt), *values)
        view = {"buffer": 0, "byteOffset": len(self.buf), "byteLength": len(data)}
        if target:
            view["target"] = target
        self.views.append(view)
        self.buf += data
        acc = {"bufferView": len(self.views) - 1, "componentType": ctype, "count": count, "type": atype}
        if minmax:
            n = len(values) // count
            acc["min"] = [min(values[i::n]) for i in range(n)]
            acc["max"] = [max(values[i::n]) for i in range(n)]
        self.accessors.append(acc)
        return len(self.accessors) - 1

    def document(self, name, doc):
        doc["asset"] = {"version": "2.0", "generator": "Specula tests/assets/gltf/make_animated.py"}
        doc["accessors"] = self.accessors
        doc["bufferViews"] = self.views
        doc["buffers"] = [{"byteLength": len(self.buf),
                           "uri": "data:application/octet-stream;base64," + base64.b64encode(self.buf).decode()}]
        open(name, "w").write(json.dumps(doc, indent=1) + "\n")


def bend_weight(y):
    return min(max((y - 0.75) / 0.5, 0.0), 1.0)


def skinned_bar():
    b = Builder()
    pos, nrm, j0, w0, j1, w1, idx = [], [], [], [], [], [], []
    h = 0.1
    rings = [0.25 * i for i in range(9)]
    # four sides, each with its own vertices (flat normals): (corner a, corner b, normal)
    sides = [((-h, h), (h, h), (0, 1)), ((h, h), (h, -h), (1, 0)), ((h, -h), (-h, -h), (0, -1)), ((-h, -h), (-h, h), (-1, 0))]

    def vertex(x, y, z, n):
        pos.extend([x, y, z]); nrm.extend(n)
        w = bend_weight(y)
        j0.extend([0, 0, 0, 0]); w0.extend([1.0 - w, 0.0, 0.0, 0.0])
        j1.extend([1 if w > 0 else 0, 0, 0, 0]); w1.extend([w, 0.0, 0.0, 0.0])
        return len(pos) // 3 - 1

    for (ax, az), (bx, bz), (nx, nz) in sides:
        first = len(pos) // 3
        for y in rings:
            vertex(ax, y, az, [nx, 0, nz]); vertex(bx, y, bz, [nx, 0, nz])
        for r in range(len(rings) - 1):
            a, bb, c, d = first + 2 * r, first + 2 * r + 1, first + 2 * r + 2, first + 2 * r + 3
            # counter-clockwise seen from outside (a, b along the bottom, c, d above them)
            idx.extend([a, bb, c, bb, d, c])
    for y, ny in ((0.0, -1), (2.0, 1)):
        q = [vertex(x, y, z, [0, ny, 0]) for (x, z) in ((-h, -h), (h, -h), (h, h), (-h, h))]
        idx.extend([q[0], q[1], q[2], q[0], q[2], q[3]] if ny < 0 else [q[0], q[2], q[1], q[0], q[3], q[2]])
    n = len(pos) // 3
    a_pos = b.add("f", pos, 5126, "VEC3", n, 34962, minmax=True)
    a_nrm = b.add("f", nrm, 5126, "VEC3", n, 34962)
    a_j0 = b.add("B", j0, 5121, "VEC4", n, 34962)
    a_w0 = b.add("f", w0, 5126, "VEC4", n, 34962)
    a_j1 = b.add("B", j1, 5121, "VEC4", n, 34962)
    a_w1 = b.add("f", w1, 5126, "VEC4", n, 34962)
    a_idx = b.add("H", idx, 5123, "SCALAR", len(idx), 34963)
    # ground
    g = 3.0
    gpos = [-g, -0.05, g, g, -0.05, g, g, -0.05, -g, -g, -0.05, -g]
    a_gpos = b.add("f", gpos, 5126, "VEC3", 4, 34962, minmax=True)
    a_gnrm = b.add("f", [0, 1, 0] * 4, 5126, "VEC3", 4, 34962)
    a_gidx = b.add("H", [0, 1, 2, 0, 2, 3], 5123, "SCALAR", 6, 34963)
    # inverse bind matrices (column major): identity, and translate(0, -1, 0)
    ibm = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1] + [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -1, 0, 1]
    a_ibm = b.add("f", ibm, 5126, "MAT4", 2)
    # animations
    a_t = b.add("f", [0.0, 1.0], 5126, "SCALAR", 2, minmax=True)
    s45 = math.sin(math.radians(45))
    a_rot = b.add("f", [0, 0, 0, 1, 0, 0, s45, s45], 5126, "VEC4", 2)
    a_lift = b.add("f", [0, 0, 0, 0, 0.5, 0], 5126, "VEC3", 2)
    b.document("skinned_bar.gltf", {
        "scene": 0, "scenes": [{"nodes": [0, 1, 3]}],
        "nodes": [{"name": "bar", "mesh": 0, "skin": 0},
                  {"name": "root joint", "children": [2]},
                  {"name": "bend joint", "translation": [0, 1, 0]},
                  {"name": "ground", "mesh": 1}],
        "skins": [{"name": "bar skin", "joints": [1, 2], "inverseBindMatrices": a_ibm, "skeleton": 1}],
        "meshes": [{"name": "bar", "primitives": [{"attributes": {"POSITION": a_pos, "NORMAL": a_nrm,
                    "JOINTS_0": a_j0, "WEIGHTS_0": a_w0, "JOINTS_1": a_j1, "WEIGHTS_1": a_w1}, "indices": a_idx, "material": 0}]},
                   {"name": "ground", "primitives": [{"attributes": {"POSITION": a_gpos, "NORMAL": a_gnrm}, "indices": a_gidx, "material": 1}]}],
        "materials": [{"name": "bar", "pbrMetallicRoughness": {"baseColorFactor": [0.9, 0.9, 0.9, 1], "metallicFactor": 0, "roughnessFactor": 0.8}},
                      {"name": "ground", "pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.5, 0.5, 1], "metallicFactor": 0, "roughnessFactor": 0.9}}],
        "animations": [
            {"name": "bend", "samplers": [{"input": a_t, "output": a_rot, "interpolation": "LINEAR"}],
             "channels": [{"sampler": 0, "target": {"node": 2, "path": "rotation"}}]},
            {"name": "lift", "samplers": [{"input": a_t, "output": a_lift, "interpolation": "STEP"}],
             "channels": [{"sampler": 0, "target": {"node": 1, "path": "translation"}}]}],
    })


def morph_quad():
    b = Builder()
    pos = [-0.5, -0.5, 0, 0.5, -0.5, 0, 0.5, 0.5, 0, -0.5, 0.5, 0]
    a_pos = b.add("f", pos, 5126, "VEC3", 4, 34962, minmax=True)
    a_nrm = b.add("f", [0, 0, 1] * 4, 5126, "VEC3", 4, 34962)
    a_idx = b.add("H", [0, 1, 2, 0, 2, 3], 5123, "SCALAR", 6, 34963)
    a_up = b.add("f", [0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 1, 0], 5126, "VEC3", 4, 34962, minmax=True)
    a_right = b.add("f", [0, 0, 0, 0.5, 0, 0, 0.5, 0, 0, 0, 0, 0], 5126, "VEC3", 4, 34962, minmax=True)
    a_t = b.add("f", [0.0, 1.0], 5126, "SCALAR", 2, minmax=True)
    a_w = b.add("f", [0, 0, 1, 0.5], 5126, "SCALAR", 4)
    b.document("morph_quad.gltf", {
        "scene": 0, "scenes": [{"nodes": [0]}],
        "nodes": [{"name": "quad", "mesh": 0}],
        "meshes": [{"name": "quad", "weights": [0.25, 0.0],
                    "primitives": [{"attributes": {"POSITION": a_pos, "NORMAL": a_nrm}, "indices": a_idx, "material": 0,
                                    "targets": [{"POSITION": a_up}, {"POSITION": a_right}]}]}],
        "materials": [{"name": "quad", "doubleSided": True,
                       "pbrMetallicRoughness": {"baseColorFactor": [0.9, 0.9, 0.9, 1], "metallicFactor": 0, "roughnessFactor": 0.8}}],
        "animations": [{"name": "grow", "samplers": [{"input": a_t, "output": a_w, "interpolation": "LINEAR"}],
                        "channels": [{"sampler": 0, "target": {"node": 0, "path": "weights"}}]}],
    })


skinned_bar()
morph_quad()
