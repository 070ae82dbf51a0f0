# Writes iridescence_quad.gltf (run in this directory; the output is committed).
# One 2 x 2 quad facing +Z (normals +Z), a grey rough metal under a KHR_materials_iridescence
# film whose strength and thickness come from textures, so every texel is known exactly
# (tests/gl/test_iridescence.cpp):
#   iridescenceFactor 1 x iridescenceTexture R 230/255 (1 x 1 PNG);
#   thickness mix(100, 700 nm, G) from a 2 x 2 PNG, G = 0, 85 (top row), 170, 255 (bottom row):
#   100, 300, 500 and 700 nm, sampled NEAREST, clamped, through KHR_texture_transform
#   (offset (1, 0), scale (-1, 1): u' = 1 - u, the columns swapped), texCoord 0.
import json

from quad import png, quad, uri

buf, bv, acc = quad(tangents=False, uv1=False)
strength = png(1, 1, [[230, 0, 0]])
thickness = png(2, 2, [[0, 0, 0, 0, 85, 0], [0, 170, 0, 0, 255, 0]])
doc = {
    "asset": {"version": "2.0", "generator": "Specula tests/assets/gltf/make_iridescence.py"},
    "extensionsUsed": ["KHR_materials_iridescence", "KHR_texture_transform"],
    "scene": 0, "scenes": [{"nodes": [0]}],
    "nodes": [{"mesh": 0, "name": "quad"}],
    "meshes": [{"name": "quad", "primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2},
                                                 "indices": 3, "material": 0}]}],
    "materials": [{
        "name": "film",
        "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.8, 0.8, 1.0], "metallicFactor": 1.0, "roughnessFactor": 0.45},
        "extensions": {"KHR_materials_iridescence": {
            "iridescenceFactor": 1.0, "iridescenceTexture": {"index": 0},
            "iridescenceIor": 1.6,
            "iridescenceThicknessMinimum": 100.0, "iridescenceThicknessMaximum": 700.0,
            "iridescenceThicknessTexture": {"index": 1, "texCoord": 0, "extensions": {
                "KHR_texture_transform": {"offset": [1.0, 0.0], "scale": [-1.0, 1.0]}}}}}}],
    "samplers": [{"magFilter": 9728, "minFilter": 9728, "wrapS": 33071, "wrapT": 33071}],
    "textures": [{"source": 0, "sampler": 0}, {"source": 1, "sampler": 0}],
    "images": [{"name": "iridescence", "mimeType": "image/png", "uri": uri(strength, "image/png")},
               {"name": "iridescence thickness", "mimeType": "image/png", "uri": uri(thickness, "image/png")}],
    "accessors": acc, "bufferViews": bv,
    "buffers": [{"byteLength": len(buf), "uri": uri(buf, "application/octet-stream")}],
}
open("iridescence_quad.gltf", "w").write(json.dumps(doc, indent=1) + "\n")
