# Writes specular_glossiness_quad.gltf (run in this directory; the output is committed).
# One 2 x 2 quad facing +Z (normals +Z) under the archived KHR_materials_pbrSpecularGlossiness,
# with a metal-rough fallback (a smooth metal) that the extension replaces
# (tests/unit/test_gltf.cpp):
#   diffuseFactor (0.8, 0.9, 1, 1) x diffuseTexture, a 2 x 1 sRGB PNG: (255, 200, 150), (90, 160, 220);
#   specularFactor (0.9, 0.8, 0.7), glossinessFactor 0.8 x specularGlossinessTexture, a 2 x 1
#   RGBA PNG: texel 0 (200, 150, 100, A 255), texel 1 (60, 60, 60, A 64); NEAREST, texCoord 0.
import json

from quad import png, quad, uri

buf, bv, acc = quad(tangents=False, uv1=False)
doc = {
    "asset": {"version": "2.0", "generator": "Specula tests/assets/gltf/make_specular_glossiness.py"},
    "extensionsUsed": ["KHR_materials_pbrSpecularGlossiness"],
    "scene": 0, "scenes": [{"nodes": [0]}],
    "nodes": [{"mesh": 0, "name": "quad"}],
    "meshes": [{"name": "quad", "primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2},
                                                 "indices": 3, "material": 0}]}],
    "materials": [{
        "name": "spec-gloss",
        "pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.5, 0.5, 1.0], "metallicFactor": 1.0, "roughnessFactor": 0.1},
        "extensions": {"KHR_materials_pbrSpecularGlossiness": {
            "diffuseFactor": [0.8, 0.9, 1.0, 1.0], "diffuseTexture": {"index": 0},
            "specularFactor": [0.9, 0.8, 0.7], "glossinessFactor": 0.8,
            "specularGlossinessTexture": {"index": 1}}}}],
    "samplers": [{"magFilter": 9728, "minFilter": 9728}],
    "textures": [{"source": 0, "sampler": 0}, {"source": 1, "sampler": 0}],
    "images": [{"name": "diffuse", "mimeType": "image/png", "uri": uri(png(2, 1, [[255, 200, 150, 90, 160, 220]]), "image/png")},
               {"name": "specular glossiness", "mimeType": "image/png",
                "uri": uri(png(2, 1, [[200, 150, 100, 255, 60, 60, 60, 64]], 4), "image/png")}],
    "accessors": acc, "bufferViews": bv,
    "buffers": [{"byteLength": len(buf), "uri": uri(buf, "application/octet-stream")}],
}
open("specular_glossiness_quad.gltf", "w").write(json.dumps(doc, indent=1) + "\n")
