# Writes sheen_quad.gltf (run in this directory; the output is committed).
# One 2 x 2 quad facing +Z (normals +Z), a rough dark blue dielectric under KHR_materials_sheen
# whose colour and roughness come from textures, so that every texel is known exactly
# (tests/gl/test_sheen.cpp):
#   sheenColorFactor (0.9, 1, 0.8) x sheenColorTexture, a 2 x 1 sRGB PNG: texel 0 (255, 128, 64),
#   texel 1 (64, 160, 255), sampled NEAREST with REPEAT through texCoord 1 (u1 = 1 - u0, v1 = v0)
#   and KHR_texture_transform offset (0.5, 0): texel 0 on the quad's left half (x < 0), texel 1
#   on its right; either the transform or the texCoord alone would swap them.
#   sheenRoughnessFactor 0.8 x sheenRoughnessTexture A 153/255 (a 1 x 1 RGBA PNG, RGB unused).
import json

from quad import png, quad, uri

buf, bv, acc = quad(tangents=False, uv1=True)
doc = {
    "asset": {"version": "2.0", "generator": "Specula tests/assets/gltf/make_sheen.py"},
    "extensionsUsed": ["KHR_materials_sheen", "KHR_texture_transform"],
    "scene": 0, "scenes": [{"nodes": [0]}],
    "nodes": [{"mesh": 0, "name": "quad"}],
    "meshes": [{"name": "quad", "primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2, "TEXCOORD_1": 3},
                                                 "indices": 4, "material": 0}]}],
    "materials": [{
        "name": "velvet",
        "pbrMetallicRoughness": {"baseColorFactor": [0.05, 0.08, 0.3, 1.0], "metallicFactor": 0.0, "roughnessFactor": 0.8},
        "extensions": {"KHR_materials_sheen": {
            "sheenColorFactor": [0.9, 1.0, 0.8],
            "sheenColorTexture": {"index": 0, "texCoord": 1,
                                  "extensions": {"KHR_texture_transform": {"offset": [0.5, 0.0]}}},
            "sheenRoughnessFactor": 0.8, "sheenRoughnessTexture": {"index": 1}}}}],
    "samplers": [{"magFilter": 9728, "minFilter": 9728}],
    "textures": [{"source": 0, "sampler": 0}, {"source": 1, "sampler": 0}],
    "images": [{"name": "sheen colour", "mimeType": "image/png", "uri": uri(png(2, 1, [[255, 128, 64, 64, 160, 255]]), "image/png")},
               {"name": "sheen roughness", "mimeType": "image/png", "uri": uri(png(1, 1, [[0, 0, 0, 153]], 4), "image/png")}],
    "accessors": acc, "bufferViews": bv,
    "buffers": [{"byteLength": len(buf), "uri": uri(buf, "application/octet-stream")}],
}
open("sheen_quad.gltf", "w").write(json.dumps(doc, indent=1) + "\n")
