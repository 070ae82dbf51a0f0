# Writes transmission_quad.gltf (run in this directory; the output is committed).
# One 2 x 2 quad facing +Z (normals +Z), a white smooth dielectric that lets light through
# (KHR_materials_transmission) into a volume (KHR_materials_volume), both scaled by textures, so
# that every texel is known exactly (tests/gl/test_transparency.cpp):
#   transmissionFactor 0.9 x transmissionTexture R: a 2 x 1 RGB PNG, texel 0 (128, 255, 0),
#   texel 1 (255, 64, 0), sampled NEAREST through texCoord 0: texel 0 on the quad's left half
#   (x < 0), texel 1 on its right.
#   thicknessFactor 0.5 x thicknessTexture G: a second 2 x 1 RGB PNG, texel 0 (64, 255, 0),
#   texel 1 (255, 64, 0), through texCoord 1 (u1 = 1 - u0, v1 = v0) and KHR_texture_transform
#   offset (0.5, 0): texel 0 on the left half too (either the transform or the texCoord alone
#   would swap them); attenuation colour (0.9, 0.5, 0.2) after 0.25 m.
# Read with the wrong channel (G for the transmission, R for the thickness) either texture
# gives other values on both halves.
import json

from quad import png, quad, uri

buf, bv, acc = quad(tangents=False, uv1=True)
doc = {
    "asset": {"version": "2.0", "generator": "Specula tests/assets/gltf/make_transmission.py"},
    "extensionsUsed": ["KHR_materials_transmission", "KHR_materials_volume", "KHR_texture_transform"],
    "scene": 0, "scenes": [{"nodes": [0]}],
    "nodes": [{"mesh": 0, "name": "quad"}],
    "meshes": [{"name": "quad", "primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2, "TEXCOORD_1": 3},
                                                 "indices": 4, "material": 0}]}],
    "materials": [{
        "name": "tinted glass",
        "pbrMetallicRoughness": {"baseColorFactor": [1.0, 1.0, 1.0, 1.0], "metallicFactor": 0.0, "roughnessFactor": 0.0},
        "extensions": {
            "KHR_materials_transmission": {"transmissionFactor": 0.9, "transmissionTexture": {"index": 0}},
            "KHR_materials_volume": {
                "thicknessFactor": 0.5,
                "thicknessTexture": {"index": 1, "texCoord": 1,
                                     "extensions": {"KHR_texture_transform": {"offset": [0.5, 0.0]}}},
                "attenuationDistance": 0.25, "attenuationColor": [0.9, 0.5, 0.2]}}}],
    "samplers": [{"magFilter": 9728, "minFilter": 9728}],
    "textures": [{"source": 0, "sampler": 0}, {"source": 1, "sampler": 0}],
    "images": [{"name": "transmission", "mimeType": "image/png", "uri": uri(png(2, 1, [[128, 255, 0, 255, 64, 0]]), "image/png")},
               {"name": "thickness", "mimeType": "image/png", "uri": uri(png(2, 1, [[64, 255, 0, 255, 64, 0]]), "image/png")}],
    "accessors": acc, "bufferViews": bv,
    "buffers": [{"byteLength": len(buf), "uri": uri(buf, "application/octet-stream")}],
}
open("transmission_quad.gltf", "w").write(json.dumps(doc, indent=1) + "\n")
