# Writes unlit_quads.gltf (run in this directory; the output is committed).
# Two quads facing +Z: the left one KHR_materials_unlit, the right one the same factors lit (PBR).
import base64, json, struct
pos, nrm, col, idx = [], [], [], []
for q, x0 in enumerate((-1.1, 0.1)):
    base = len(pos) // 3
    for (x, y) in ((0, 0), (1, 0), (1, 1), (0, 1)):
        pos += [x0 + x, y - 0.5, 0.0]; nrm += [0, 0, 1]
    # vertex colours: a gradient in red, 1 in green and blue
    col += [1, 1, 1, 1, 0.5, 1, 1, 1, 0.5, 1, 1, 1, 1, 1, 1, 1]
    idx += [base, base + 1, base + 2, base, base + 2, base + 3]
def pack(fmt, v): return struct.pack("<%d%s" % (len(v), fmt), *v)
views = [pack("f", pos), pack("f", nrm), pack("f", col)]
buf = b""; bv = []
for v in views:
    bv.append({"buffer": 0, "byteOffset": len(buf), "byteLength": len(v), "target": 34962}); buf += v
acc = [
    {"bufferView": 0, "componentType": 5126, "count": 8, "type": "VEC3",
     "min": [min(pos[0::3]), min(pos[1::3]), 0.0], "max": [max(pos[0::3]), max(pos[1::3]), 0.0]},
    {"bufferView": 1, "componentType": 5126, "count": 8, "type": "VEC3"},
    {"bufferView": 2, "componentType": 5126, "count": 8, "type": "VEC4"},
]
meshes = []
for k in range(2):
    data = pack("H", idx[6 * k:6 * k + 6])
    while len(buf) % 4: buf += b"\0"
    bv.append({"buffer": 0, "byteOffset": len(buf), "byteLength": len(data), "target": 34963}); buf += data
    acc.append({"bufferView": len(bv) - 1, "componentType": 5123, "count": 6, "type": "SCALAR"})
    meshes.append({"name": ["unlit", "lit"][k], "primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "COLOR_0": 2},
                   "indices": len(acc) - 1, "material": k}]})
material = {"pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.8, 0.2, 1.0], "metallicFactor": 0.0, "roughnessFactor": 0.9},
            "emissiveFactor": [1.0, 0.0, 1.0]}
doc = {
    "asset": {"version": "2.0", "generator": "Specula tests/assets/gltf/make_unlit.py"},
    "extensionsUsed": ["KHR_materials_unlit"],
    "scene": 0, "scenes": [{"nodes": [0, 1]}],
    "nodes": [{"mesh": 0, "name": "unlit"}, {"mesh": 1, "name": "lit"}],
    "meshes": meshes,
    "materials": [dict(material, name="unlit", extensions={"KHR_materials_unlit": {}}), dict(material, name="lit")],
    "accessors": acc, "bufferViews": bv,
    "buffers": [{"byteLength": len(buf), "uri": "data:application/octet-stream;base64," + base64.b64encode(buf).decode()}],
}
open("unlit_quads.gltf", "w").write(json.dumps(doc, indent=1) + "\n")
