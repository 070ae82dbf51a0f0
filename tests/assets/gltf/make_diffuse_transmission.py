# Writes diffuse_transmission_quad.gltf (run in this directory; the output is committed).
# One 2 x 2 double-sided quad facing +Z (normals +Z), a green, partly metallic dielectric under
# KHR_materials_diffuse_transmission whose strength and colour come from textures, so that
# every texel is known exactly (tests/gl/test_diffuse_transmission.cpp):
#   diffuseTransmissionFactor 0.8 x diffuseTransmissionTexture A: a 2 x 1 RGBA PNG, texel 0 A 96,
#   texel 1 A 255 (its RGB, unused, differ), sampled NEAREST through texCoord 0: texel 0 on the
#   quad's left half (x < 0), texel 1 on its right.
#   diffuseTransmissionColorFactor (1, 0.9, 0.7) x diffuseTransmissionColorTexture, a 2 x 1 sRGB
#   PNG: texel 0 (255, 64, 32), texel 1 (128, 255, 96), through texCoord 1 (u1 = 1 - u0, v1 = v0)
#   and KHR_texture_transform offset (0.5, 0): texel 0 on the left half too; either the transform
#   or the texCoord alone would swap them.
import json

from quad import png, quad, uri

buf, bv, acc = quad(tangents=False, uv1=True)
doc = {
    "asset": {"version": "2.0", "generator": "Specula tests/assets/gltf/make_diffuse_transmission.py"},
    "extensionsUsed": ["KHR_materials_diffuse_transmission", "KHR_texture_transform"],
    "scene": 0, "scenes": [{"nodes": [0]}],
    "nodes": [{"mesh": 0, "name": "quad"}],
    "meshes": [{"name": "quad", "primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2, "TEXCOORD_1": 3},
                                                 "indices": 4, "material": 0}]}],
    "materials": [{
        "name": "leaf",
        "doubleSided": True,
        "pbrMetallicRoughness": {"baseColorFactor": [0.3, 0.6, 0.2, 1.0], "metallicFactor": 0.2, "roughnessFactor": 0.5},
        "extensions": {
            "KHR_materials_diffuse_transmission": {
                "diffuseTransmissionFactor": 0.8, "diffuseTransmissionTexture": {"index": 0},
                "diffuseTransmissionColorFactor": [1.0, 0.9, 0.7],
                "diffuseTransmissionColorTexture": {"index": 1, "texCoord": 1,
                                                    "extensions": {"KHR_texture_transform": {"offset": [0.5, 0.0]}}}}}}],
    "samplers": [{"magFilter": 9728, "minFilter": 9728}],
    "textures": [{"source": 0, "sampler": 0}, {"source": 1, "sampler": 0}],
    "images": [{"name": "strength", "mimeType": "image/png", "uri": uri(png(2, 1, [[10, 200, 90, 96, 200, 10, 90, 255]], 4), "image/png")},
               {"name": "colour", "mimeType": "image/png", "uri": uri(png(2, 1, [[255, 64, 32, 128, 255, 96]]), "image/png")}],
    "accessors": acc, "bufferViews": bv,
    "buffers": [{"byteLength": len(buf), "uri": uri(buf, "application/octet-stream")}],
}
open("diffuse_transmission_quad.gltf", "w").write(json.dumps(doc, indent=1) + "\n")
