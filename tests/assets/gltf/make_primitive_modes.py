# Writes primitive_modes.gltf (run in this directory; the output is committed).
# The glTF primitive modes besides triangles, each in the z = 0 plane with its own colour, every
# vertex known exactly (tests/gl/test_primitive_modes.cpp, tests/unit/test_gltf.cpp):
#   mesh 0 "points", POINTS (non-indexed): (-3, 1.5), (-2, 1.5), (-1, 1.5), (-3, 0.5), unlit red;
#   mesh 1 "lines", LINES (indexed, unsigned bytes):
#     (0, 1.5)-(2, 1.5) and (0, 0.5)-(2, 1.0), unlit green;
#   mesh 2 "strip", LINE_STRIP (non-indexed): (-3, -0.5), (-1, -0.5), (-1, -1.5), unlit blue;
#   mesh 3 "loop", LINE_LOOP (indexed, unsigned shorts): the square (0.5, -0.5), (1.5, -0.5),
#     (1.5, -1.5), (0.5, -1.5), closed back to its first vertex, a lit yellow material (no
#     KHR_materials_unlit) but no NORMAL: drawn unlit, yellow;
#   mesh 4 "lit", LINES with NORMAL (0, 0, 1): (2.5, 0)-(3.5, 0), a Lambertian white (base 0.8,
#     KHR_materials_specular factor 0) lit by a directional light of 2 lux shining along -Z.
import json, struct

from quad import uri

def pack(fmt, v): return struct.pack("<%d%s" % (len(v), fmt), *v)
buf = b""; bv = []; acc = []
def add(data, count, kind, component=5126, target=34962, bounds=None):
    global buf
    while len(buf) % 4: buf += b"\0"
    bv.append({"buffer": 0, "byteOffset": len(buf), "byteLength": len(data), "target": target})
    buf += data
    a = {"bufferView": len(bv) - 1, "componentType": component, "count": count, "type": kind}
    if bounds: a.update({"min": bounds[0], "max": bounds[1]})
    acc.append(a)
    return len(acc) - 1
def positions(points):
    flat = [c for p in points for c in (p[0], p[1], 0.0)]
    lo = [min(p[k] if k < 2 else 0.0 for p in points) for k in range(3)]
    hi = [max(p[k] if k < 2 else 0.0 for p in points) for k in range(3)]
    return add(pack("f", flat), len(points), "VEC3", bounds=(lo, hi))

points = positions([(-3, 1.5), (-2, 1.5), (-1, 1.5), (-3, 0.5)])
lines = positions([(0, 1.5), (2, 1.5), (0, 0.5), (2, 1.0)])
line_indices = add(bytes([0, 1, 2, 3]), 4, "SCALAR", component=5121, target=34963)
strip = positions([(-3, -0.5), (-1, -0.5), (-1, -1.5)])
loop = positions([(0.5, -0.5), (1.5, -0.5), (1.5, -1.5), (0.5, -1.5)])
loop_indices = add(pack("H", [0, 1, 2, 3]), 4, "SCALAR", component=5123, target=34963)
lit = positions([(2.5, 0.0), (3.5, 0.0)])
lit_normals = add(pack("f", [0, 0, 1, 0, 0, 1]), 2, "VEC3")

def unlit(name, colour):
    return {"name": name, "pbrMetallicRoughness": {"baseColorFactor": colour + [1.0]}, "extensions": {"KHR_materials_unlit": {}}}
doc = {
    "asset": {"version": "2.0", "generator": "Specula tests/assets/gltf/make_primitive_modes.py"},
    "extensionsUsed": ["KHR_materials_unlit", "KHR_materials_specular", "KHR_lights_punctual"],
    "scene": 0, "scenes": [{"nodes": [0, 1, 2, 3, 4, 5]}],
    "nodes": [{"mesh": m, "name": n} for m, n in enumerate(["points", "lines", "strip", "loop", "lit"])] +
             [{"name": "sun", "extensions": {"KHR_lights_punctual": {"light": 0}}}],
    "meshes": [{"name": "points", "primitives": [{"attributes": {"POSITION": points}, "mode": 0, "material": 0}]},
               {"name": "lines", "primitives": [{"attributes": {"POSITION": lines}, "indices": line_indices, "mode": 1, "material": 1}]},
               {"name": "strip", "primitives": [{"attributes": {"POSITION": strip}, "mode": 3, "material": 2}]},
               {"name": "loop", "primitives": [{"attributes": {"POSITION": loop}, "indices": loop_indices, "mode": 2, "material": 3}]},
               {"name": "lit", "primitives": [{"attributes": {"POSITION": lit, "NORMAL": lit_normals}, "mode": 1, "material": 4}]}],
    "materials": [unlit("red", [1.0, 0.0, 0.0]), unlit("green", [0.0, 1.0, 0.0]), unlit("blue", [0.0, 0.0, 1.0]),
                  {"name": "yellow", "pbrMetallicRoughness": {"baseColorFactor": [1.0, 1.0, 0.0, 1.0], "metallicFactor": 0.0,
                                                              "roughnessFactor": 1.0},
                   "extensions": {"KHR_materials_specular": {"specularFactor": 0.0}}},
                  {"name": "white", "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.8, 0.8, 1.0], "metallicFactor": 0.0,
                                                             "roughnessFactor": 1.0},
                   "extensions": {"KHR_materials_specular": {"specularFactor": 0.0}}}],
    "extensions": {"KHR_lights_punctual": {"lights": [{"type": "directional", "intensity": 2.0, "name": "sun"}]}},
    "accessors": acc, "bufferViews": bv,
    "buffers": [{"byteLength": len(buf), "uri": uri(buf, "application/octet-stream")}],
}
open("primitive_modes.gltf", "w").write(json.dumps(doc, indent=1) + "\n")
