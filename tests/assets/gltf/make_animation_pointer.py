# Writes animation_pointer.gltf (run in this directory; the output is committed).
# KHR_animation_pointer on two quads and a light, every value known exactly
# (tests/gl/test_animation_pointer.cpp, tests/unit/test_gltf.cpp):
#   node 0, "screen": the 2 x 2 quad at x = -1.1, an unlit material (KHR_materials_unlit) whose
#     baseColorFactor is (0.5, 0.5, 0.5, 1) in the file and goes LINEAR from (1, 0, 0, 1) at 0 s to
#     (0, 0, 1, 1) at 1 s, times a 2 x 1 sRGB texture (white, then grey 128) sampled NEAREST,
#     whose KHR_texture_transform offset (0, 0) in the file goes STEP to (0.5, 0) at 0.5 s: the
#     halves swap texels.
#   node 1, "card": the quad at x = 1.1 (translation (1.1, 0, 0), animated through the pointer
#     /nodes/1/translation LINEAR to (1.1, 0.5, 0) at 1 s), a white Lambertian material (base 0.8,
#     KHR_materials_specular's factor 0: no specular lobe).
#   node 2, "lamp": a point light (KHR_lights_punctual) at (1.1, 0, 1.5), intensity 1.5 cd in the
#     file, LINEAR from 2 cd at 0 s to 6 cd at 1 s; its colour white, STEP to (1, 0.5, 0.25) at 0.5 s.
#   One channel points at /materials/0/extras/glow, an application's own property, which Specula
#   does not animate (a warning).
#   node 3, "camera": a perspective camera (yfov 0.6, znear 0.1, zfar 50) at (0, 0, 6), moved by
#     a core translation channel LINEAR to (0.5, 0, 6) at 1 s; its yfov through the pointer
#     /cameras/0/perspective/yfov LINEAR from 0.6 to 0.9.
import json, struct

from quad import png, quad, uri

buf, bv, acc = quad(tangents=False, uv1=False)
def pack(fmt, v): return struct.pack("<%d%s" % (len(v), fmt), *v)
def add(data, count, kind):
    global buf
    while len(buf) % 4: buf += b"\0"
    bv.append({"buffer": 0, "byteOffset": len(buf), "byteLength": len(data)})
    buf += data
    acc.append({"bufferView": len(bv) - 1, "componentType": 5126, "count": count, "type": kind})
    return len(acc) - 1

t01 = add(pack("f", [0.0, 1.0]), 2, "SCALAR"); acc[t01].update({"min": [0.0], "max": [1.0]})
t0h = add(pack("f", [0.0, 0.5]), 2, "SCALAR"); acc[t0h].update({"min": [0.0], "max": [0.5]})
colour = add(pack("f", [1, 0, 0, 1, 0, 0, 1, 1]), 2, "VEC4")
offset = add(pack("f", [0, 0, 0.5, 0]), 2, "VEC2")
move = add(pack("f", [1.1, 0, 0, 1.1, 0.5, 0]), 2, "VEC3")
intensity = add(pack("f", [2.0, 6.0]), 2, "SCALAR")
light_colour = add(pack("f", [1, 1, 1, 1, 0.5, 0.25]), 2, "VEC3")
glow = add(pack("f", [0.25, 0.75]), 2, "SCALAR")
camera_move = add(pack("f", [0, 0, 6, 0.5, 0, 6]), 2, "VEC3")
yfov = add(pack("f", [0.6, 0.9]), 2, "SCALAR")

def pointer(sampler, path):
    return {"sampler": sampler, "target": {"path": "pointer", "extensions": {"KHR_animation_pointer": {"pointer": path}}}}

doc = {
    "asset": {"version": "2.0", "generator": "Specula tests/assets/gltf/make_animation_pointer.py"},
    "extensionsUsed": ["KHR_animation_pointer", "KHR_lights_punctual", "KHR_materials_unlit", "KHR_materials_specular",
                       "KHR_texture_transform"],
    "scene": 0, "scenes": [{"nodes": [0, 1, 2, 3]}],
    "nodes": [{"mesh": 0, "name": "screen", "translation": [-1.1, 0, 0]},
              {"mesh": 1, "name": "card", "translation": [1.1, 0, 0]},
              {"name": "lamp", "translation": [1.1, 0, 1.5], "extensions": {"KHR_lights_punctual": {"light": 0}}},
              {"name": "camera", "translation": [0, 0, 6], "camera": 0}],
    "cameras": [{"type": "perspective", "perspective": {"yfov": 0.6, "znear": 0.1, "zfar": 50}}],
    "meshes": [{"name": "screen", "primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}, "indices": 3, "material": 0}]},
               {"name": "card", "primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}, "indices": 3, "material": 1}]}],
    "materials": [
        {"name": "screen", "pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.5, 0.5, 1.0],
                                                    "baseColorTexture": {"index": 0, "extensions": {"KHR_texture_transform": {"offset": [0, 0]}}}},
         "extensions": {"KHR_materials_unlit": {}}, "extras": {"glow": 0.0}},
        {"name": "card", "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.8, 0.8, 1.0], "metallicFactor": 0.0, "roughnessFactor": 1.0},
         "extensions": {"KHR_materials_specular": {"specularFactor": 0.0}}}],
    "extensions": {"KHR_lights_punctual": {"lights": [{"type": "point", "intensity": 1.5, "name": "lamp"}]}},
    "samplers": [{"magFilter": 9728, "minFilter": 9728}],
    "textures": [{"source": 0, "sampler": 0}],
    "images": [{"name": "two texels", "mimeType": "image/png", "uri": uri(png(2, 1, [[255, 255, 255, 128, 128, 128]]), "image/png")}],
    "animations": [{"name": "pointers",
                    "samplers": [{"input": t01, "output": colour, "interpolation": "LINEAR"},
                                 {"input": t0h, "output": offset, "interpolation": "STEP"},
                                 {"input": t01, "output": move, "interpolation": "LINEAR"},
                                 {"input": t01, "output": intensity, "interpolation": "LINEAR"},
                                 {"input": t0h, "output": light_colour, "interpolation": "STEP"},
                                 {"input": t01, "output": glow, "interpolation": "LINEAR"},
                                 {"input": t01, "output": camera_move, "interpolation": "LINEAR"},
                                 {"input": t01, "output": yfov, "interpolation": "LINEAR"}],
                    "channels": [pointer(0, "/materials/0/pbrMetallicRoughness/baseColorFactor"),
                                 pointer(1, "/materials/0/pbrMetallicRoughness/baseColorTexture/extensions/KHR_texture_transform/offset"),
                                 pointer(2, "/nodes/1/translation"),
                                 pointer(3, "/extensions/KHR_lights_punctual/lights/0/intensity"),
                                 pointer(4, "/extensions/KHR_lights_punctual/lights/0/color"),
                                 pointer(5, "/materials/0/extras/glow"),
                                 {"sampler": 6, "target": {"node": 3, "path": "translation"}},
                                 pointer(7, "/cameras/0/perspective/yfov")]}],
    "accessors": acc, "bufferViews": bv,
    "buffers": [{"byteLength": len(buf), "uri": uri(buf, "application/octet-stream")}],
}
open("animation_pointer.gltf", "w").write(json.dumps(doc, indent=1) + "\n")
