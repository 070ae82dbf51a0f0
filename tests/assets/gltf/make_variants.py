# Writes variants.gltf (run in this directory; the output is committed): KHR_materials_variants.
# Two 1 x 1 quads facing +Z at z = 0, "left" centred on x = -0.6 and "right" on x = +0.6, with
# four KHR_materials_unlit materials (so a frame shows each base colour exactly):
#   0 red (0.8, 0.1, 0.1), 1 green (0.1, 0.8, 0.1), 2 blue (0.1, 0.1, 0.8),
#   3 cutout: alphaMode MASK with alpha 0, so the quad is cut out (and casts no shadow).
# Variants: 0 "Green", 1 "Blue", 2 "Hidden".
#   left:  red by default; Green -> green, Blue -> blue, Hidden -> cutout
#   right: blue by default; Green and Blue -> green (one mapping naming two variants); Hidden: no mapping
import base64, json, struct

def uri(data, mime):
    return "data:%s;base64,%s" % (mime, base64.b64encode(data).decode())

def pack(fmt, v): return struct.pack("<%d%s" % (len(v), fmt), *v)

buf = b""; bv = []; acc = []
def add(data, target, accessor):
    global buf
    while len(buf) % 4: buf += b"\0"
    bv.append({"buffer": 0, "byteOffset": len(buf), "byteLength": len(data), "target": target})
    buf += data
    accessor["bufferView"] = len(bv) - 1
    acc.append(accessor)
    return len(acc) - 1

def quad(x0):
    pos = [x0 - 0.5, -0.5, 0, x0 + 0.5, -0.5, 0, x0 + 0.5, 0.5, 0, x0 - 0.5, 0.5, 0]
    p = add(pack("f", pos), 34962, {"componentType": 5126, "count": 4, "type": "VEC3",
                                     "min": [x0 - 0.5, -0.5, 0], "max": [x0 + 0.5, 0.5, 0]})
    n = add(pack("f", [0, 0, 1] * 4), 34962, {"componentType": 5126, "count": 4, "type": "VEC3"})
    i = add(pack("H", [0, 1, 2, 0, 2, 3]), 34963, {"componentType": 5123, "count": 6, "type": "SCALAR"})
    return {"attributes": {"POSITION": p, "NORMAL": n}, "indices": i}

left = quad(-0.6)
left["material"] = 0
left["extensions"] = {"KHR_materials_variants": {"mappings": [
    {"material": 1, "variants": [0]}, {"material": 2, "variants": [1]}, {"material": 3, "variants": [2]}]}}
right = quad(0.6)
right["material"] = 2
right["extensions"] = {"KHR_materials_variants": {"mappings": [{"material": 1, "variants": [0, 1]}]}}

def unlit(name, rgba, **extra):
    m = {"name": name, "pbrMetallicRoughness": {"baseColorFactor": rgba, "metallicFactor": 0.0},
         "extensions": {"KHR_materials_unlit": {}}}
    m.update(extra)
    return m

doc = {
    "asset": {"version": "2.0", "generator": "Specula tests/assets/gltf/make_variants.py"},
    "extensionsUsed": ["KHR_materials_unlit", "KHR_materials_variants"],
    "extensions": {"KHR_materials_variants": {"variants": [{"name": "Green"}, {"name": "Blue"}, {"name": "Hidden"}]}},
    "scene": 0, "scenes": [{"nodes": [0, 1]}],
    "nodes": [{"mesh": 0, "name": "left"}, {"mesh": 1, "name": "right"}],
    "meshes": [{"name": "left", "primitives": [left]}, {"name": "right", "primitives": [right]}],
    "materials": [unlit("red", [0.8, 0.1, 0.1, 1.0]), unlit("green", [0.1, 0.8, 0.1, 1.0]),
                  unlit("blue", [0.1, 0.1, 0.8, 1.0]),
                  unlit("cutout", [0.8, 0.1, 0.1, 0.0], alphaMode="MASK", alphaCutoff=0.5)],
    "accessors": acc, "bufferViews": bv,
    "buffers": [{"byteLength": len(buf), "uri": uri(buf, "application/octet-stream")}],
}
open("variants.gltf", "w").write(json.dumps(doc, indent=1) + "\n")
