# Writes clearcoat_quad.gltf (run in this directory; the output is committed).
# One 2 x 2 quad facing +Z (normals +Z, tangents +X), a rough red dielectric under a
# KHR_materials_clearcoat layer whose factor, roughness and normal all come from textures:
# 1 x 1 PNGs, so every texel is known exactly (tests/gl/test_clearcoat.cpp).
#   clearcoatFactor 1 x clearcoatTexture R 204/255; clearcoatRoughnessFactor 0.5 x G 128/255
#   (both channels of one image); clearcoatNormalTexture (171, 128, 247): the layer's normal
#   tilted about 20 degrees towards +X (tangent), scale 0.8.
import json

from quad import png, quad, uri

buf, bv, acc = quad(tangents=True, uv1=False)
doc = {
    "asset": {"version": "2.0", "generator": "Specula tests/assets/gltf/make_clearcoat.py"},
    "extensionsUsed": ["KHR_materials_clearcoat"],
    "scene": 0, "scenes": [{"nodes": [0]}],
    "nodes": [{"mesh": 0, "name": "quad"}],
    "meshes": [{"name": "quad", "primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TANGENT": 2, "TEXCOORD_0": 3},
                                                 "indices": 4, "material": 0}]}],
    "materials": [{
        "name": "coated",
        "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.2, 0.1, 1.0], "metallicFactor": 0.0, "roughnessFactor": 0.6},
        "extensions": {"KHR_materials_clearcoat": {
            "clearcoatFactor": 1.0, "clearcoatTexture": {"index": 0},
            "clearcoatRoughnessFactor": 0.5, "clearcoatRoughnessTexture": {"index": 1},
            "clearcoatNormalTexture": {"index": 2, "scale": 0.8}}}}],
    "samplers": [{"magFilter": 9728, "minFilter": 9728}],
    "textures": [{"source": 0, "sampler": 0}, {"source": 0, "sampler": 0}, {"source": 1, "sampler": 0}],
    "images": [{"name": "clearcoat", "mimeType": "image/png", "uri": uri(png(1, 1, [[204, 128, 0]]), "image/png")},
               {"name": "clearcoat normal", "mimeType": "image/png", "uri": uri(png(1, 1, [[171, 128, 247]]), "image/png")}],
    "accessors": acc, "bufferViews": bv,
    "buffers": [{"byteLength": len(buf), "uri": uri(buf, "application/octet-stream")}],
}
open("clearcoat_quad.gltf", "w").write(json.dumps(doc, indent=1) + "\n")
