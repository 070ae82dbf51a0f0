# Writes animation_pointer_surface.gltf (run in this directory; the output is committed).
# KHR_animation_pointer on the properties of a surface that are not factors of its lobes, and on
# KHR_node_visibility; every value known exactly (tests/gl/test_animation_pointer.cpp,
# tests/unit/test_animation.cpp). Four 2 x 2 quads facing +Z (tangents +X) in a row, lit by a
# directional light of 3 lux shining along -Z ("sun"):
#   node 0, "bumped", at x = -3.3: white Lambertian (base 0.8, KHR_materials_specular factor 0: no
#     specular lobe) with a 1 x 1 normal map (204, 128, 230); normalTexture.scale 1 in the file,
#     LINEAR from 0 at 0 s to 2 at 1 s.
#   node 1, "occluded", at x = -1.1: the same material with a 1 x 1 occlusion map (R 128) instead;
#     occlusionTexture.strength 1 in the file, LINEAR from 0 to 1.
#   node 2, "cutout", at x = 1.1: unlit (KHR_materials_unlit), alphaMode MASK, white times a 4 x 1
#     RGBA texture sampled NEAREST whose alphas are 51, 102, 153, 204 (0.2 ... 0.8) across u;
#     alphaCutoff 0.5 in the file, LINEAR from 0.1 to 0.9.
#   node 3, "group", at x = 3.3: KHR_node_visibility visible false in the file, animated STEP
#     (unsigned bytes) to true at 0 s and false at 0.5 s; its children node 4, "flicker", a
#     quad of the first material without its normal map, and node 5, "bulb", a point light of
#     8 cd and range 3 m at (-1.1, 0, 0.8) from the group (x = 2.2, between the cutout and the
#     flicker quad), which reaches the occluded quad's right half too.
import json, struct

from quad import png, quad, uri

buf, bv, acc = quad(tangents=True, uv1=False)  # POSITION, NORMAL, TANGENT, TEXCOORD_0, indices
def pack(fmt, v): return struct.pack("<%d%s" % (len(v), fmt), *v)
def add(data, count, kind, component=5126):
    global buf
    while len(buf) % 4: buf += b"\0"
    bv.append({"buffer": 0, "byteOffset": len(buf), "byteLength": len(data)})
    buf += data
    acc.append({"bufferView": len(bv) - 1, "componentType": component, "count": count, "type": kind})
    return len(acc) - 1

t01 = add(pack("f", [0.0, 1.0]), 2, "SCALAR"); acc[t01].update({"min": [0.0], "max": [1.0]})
t0h = add(pack("f", [0.0, 0.5]), 2, "SCALAR"); acc[t0h].update({"min": [0.0], "max": [0.5]})
normal_scale = add(pack("f", [0.0, 2.0]), 2, "SCALAR")
strength = add(pack("f", [0.0, 1.0]), 2, "SCALAR")
cutoff = add(pack("f", [0.1, 0.9]), 2, "SCALAR")
visible = add(bytes([1, 0]), 2, "SCALAR", component=5121)

def pointer(sampler, path):
    return {"sampler": sampler, "target": {"path": "pointer", "extensions": {"KHR_animation_pointer": {"pointer": path}}}}

attributes = {"POSITION": 0, "NORMAL": 1, "TANGENT": 2, "TEXCOORD_0": 3}
lambert = {"pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.8, 0.8, 1.0], "metallicFactor": 0.0, "roughnessFactor": 1.0},
           "extensions": {"KHR_materials_specular": {"specularFactor": 0.0}}}
doc = {
    "asset": {"version": "2.0", "generator": "Specula tests/assets/gltf/make_animation_pointer_surface.py"},
    "extensionsUsed": ["KHR_animation_pointer", "KHR_lights_punctual", "KHR_materials_unlit", "KHR_materials_specular",
                       "KHR_node_visibility"],
    "scene": 0, "scenes": [{"nodes": [0, 1, 2, 3, 6]}],
    "nodes": [{"mesh": 0, "name": "bumped", "translation": [-3.3, 0, 0]},
              {"mesh": 1, "name": "occluded", "translation": [-1.1, 0, 0]},
              {"mesh": 2, "name": "cutout", "translation": [1.1, 0, 0]},
              {"name": "group", "translation": [3.3, 0, 0], "children": [4, 5],
               "extensions": {"KHR_node_visibility": {"visible": False}}},
              {"mesh": 3, "name": "flicker"},
              {"name": "bulb", "translation": [-1.1, 0, 0.8], "extensions": {"KHR_lights_punctual": {"light": 1}}},
              {"name": "sun", "extensions": {"KHR_lights_punctual": {"light": 0}}}],
    "meshes": [{"name": name, "primitives": [{"attributes": attributes, "indices": 4, "material": m}]}
               for name, m in (("bumped", 0), ("occluded", 1), ("cutout", 2), ("flicker", 3))],
    "materials": [
        dict(lambert, name="bumped", normalTexture={"index": 0, "scale": 1.0}),
        dict(lambert, name="occluded", occlusionTexture={"index": 1, "strength": 1.0}),
        {"name": "cutout", "alphaMode": "MASK", "alphaCutoff": 0.5,
         "pbrMetallicRoughness": {"baseColorFactor": [1.0, 1.0, 1.0, 1.0], "baseColorTexture": {"index": 2}},
         "extensions": {"KHR_materials_unlit": {}}},
        dict(lambert, name="flicker")],
    "extensions": {"KHR_lights_punctual": {"lights": [
        {"type": "directional", "intensity": 3.0, "name": "sun"},
        {"type": "point", "intensity": 8.0, "range": 3.0, "name": "bulb"}]}},
    "samplers": [{"magFilter": 9728, "minFilter": 9728}],
    "textures": [{"source": 0, "sampler": 0}, {"source": 1, "sampler": 0}, {"source": 2, "sampler": 0}],
    "images": [{"name": "tilted normal", "mimeType": "image/png", "uri": uri(png(1, 1, [[204, 128, 230]]), "image/png")},
               {"name": "occlusion", "mimeType": "image/png", "uri": uri(png(1, 1, [[128, 128, 128]]), "image/png")},
               {"name": "alpha ramp", "mimeType": "image/png",
                "uri": uri(png(4, 1, [[255, 255, 255, 51, 255, 255, 255, 102, 255, 255, 255, 153, 255, 255, 255, 204]], channels=4), "image/png")}],
    "animations": [{"name": "surface",
                    "samplers": [{"input": t01, "output": normal_scale, "interpolation": "LINEAR"},
                                 {"input": t01, "output": strength, "interpolation": "LINEAR"},
                                 {"input": t01, "output": cutoff, "interpolation": "LINEAR"},
                                 {"input": t0h, "output": visible, "interpolation": "STEP"}],
                    "channels": [pointer(0, "/materials/0/normalTexture/scale"),
                                 pointer(1, "/materials/1/occlusionTexture/strength"),
                                 pointer(2, "/materials/2/alphaCutoff"),
                                 pointer(3, "/nodes/3/extensions/KHR_node_visibility/visible")]}],
    "accessors": acc, "bufferViews": bv,
    "buffers": [{"byteLength": len(buf), "uri": uri(buf, "application/octet-stream")}],
}
open("animation_pointer_surface.gltf", "w").write(json.dumps(doc, indent=1) + "\n")
