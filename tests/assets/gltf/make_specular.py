# Writes specular_quad.gltf (run in this directory; the output is committed).
# One 2 x 2 quad facing +Z (normals +Z), a blue-grey dielectric of IOR 1.7 (KHR_materials_ior:
# F0 = (0.7 / 2.7)^2) under KHR_materials_specular whose strength and colour come from textures,
# so that every texel is known exactly (tests/gl/test_specular.cpp):
#   specularFactor 0.9 x specularTexture A: a 2 x 1 RGBA PNG, texel 0 A 64, texel 1 A 230 (its
#   RGB, unused, differ), sampled NEAREST through texCoord 0: texel 0 on the quad's left half
#   (x < 0), texel 1 on its right.
#   specularColorFactor (1, 0.8, 0.6) x specularColorTexture, a 2 x 1 sRGB PNG: texel 0
#   (255, 128, 64), texel 1 (64, 160, 255), through texCoord 1 (u1 = 1 - u0, v1 = v0) and
#   KHR_texture_transform offset (0.5, 0): texel 0 on the left half too; either the transform or
#   the texCoord alone would swap them.
import json

from quad import png, quad, uri

buf, bv, acc = quad(tangents=False, uv1=True)
doc = {
    "asset": {"version": "2.0", "generator": "Specula tests/assets/gltf/make_specular.py"},
    "extensionsUsed": ["KHR_materials_specular", "KHR_materials_ior", "KHR_texture_transform"],
    "scene": 0, "scenes": [{"nodes": [0]}],
    "nodes": [{"mesh": 0, "name": "quad"}],
    "meshes": [{"name": "quad", "primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2, "TEXCOORD_1": 3},
                                                 "indices": 4, "material": 0}]}],
    "materials": [{
        "name": "lacquer",
        "pbrMetallicRoughness": {"baseColorFactor": [0.2, 0.3, 0.5, 1.0], "metallicFactor": 0.0, "roughnessFactor": 0.35},
        "extensions": {
            "KHR_materials_ior": {"ior": 1.7},
            "KHR_materials_specular": {
                "specularFactor": 0.9, "specularTexture": {"index": 0},
                "specularColorFactor": [1.0, 0.8, 0.6],
                "specularColorTexture": {"index": 1, "texCoord": 1,
                                         "extensions": {"KHR_texture_transform": {"offset": [0.5, 0.0]}}}}}}],
    "samplers": [{"magFilter": 9728, "minFilter": 9728}],
    "textures": [{"source": 0, "sampler": 0}, {"source": 1, "sampler": 0}],
    "images": [{"name": "specular", "mimeType": "image/png", "uri": uri(png(2, 1, [[10, 200, 90, 64, 200, 10, 90, 230]], 4), "image/png")},
               {"name": "specular colour", "mimeType": "image/png", "uri": uri(png(2, 1, [[255, 128, 64, 64, 160, 255]]), "image/png")}],
    "accessors": acc, "bufferViews": bv,
    "buffers": [{"byteLength": len(buf), "uri": uri(buf, "application/octet-stream")}],
}
open("specular_quad.gltf", "w").write(json.dumps(doc, indent=1) + "\n")
