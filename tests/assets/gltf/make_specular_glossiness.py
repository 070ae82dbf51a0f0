# Writes specular_glossiness_quad.gltf (run in this directory; the output is committed).
# One 2 x 2 quad facing +Z (normals +Z) under the archived KHR_materials_pbrSpecularGlossiness,
# with a metal-rough fallback (a smooth metal) that the extension replaces
# (tests/unit/test_gltf.cpp):
#   diffuseFactor (0.8, 0.9, 1, 1) x diffuseTexture, a 2 x 1 sRGB PNG: (255, 200, 150), (90, 160, 220);
#   specularFactor (0.9, 0.8, 0.7), glossinessFactor 0.8 x specularGlossinessTexture, a 2 x 1
#   RGBA PNG: texel 0 (200, 150, 100, A 255), texel 1 (60, 60, 60, A 64); NEAREST, texCoord 0.
import base64, json, struct, zlib

def png(pixels, width, channels):
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xffffffff)
    raw = b"\0" + bytes(pixels)
    colour = {3: 2, 4: 6}[channels]
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, 1, 8, colour, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))

def uri(data, mime):
    return "data:%s;base64,%s" % (mime, base64.b64encode(data).decode())

pos = [-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0]
nrm = [0, 0, 1] * 4
uv0 = [0, 1, 1, 1, 1, 0, 0, 0]
idx = [0, 1, 2, 0, 2, 3]
def pack(fmt, v): return struct.pack("<%d%s" % (len(v), fmt), *v)
views = [pack("f", pos), pack("f", nrm), pack("f", uv0), pack("H", idx)]
buf = b""; bv = []
for k, v in enumerate(views):
    while len(buf) % 4: buf += b"\0"
    bv.append({"buffer": 0, "byteOffset": len(buf), "byteLength": len(v), "target": 34963 if k == 3 else 34962}); buf += v
acc = [
    {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [-1, -1, 0], "max": [1, 1, 0]},
    {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC3"},
    {"bufferView": 2, "componentType": 5126, "count": 4, "type": "VEC2"},
    {"bufferView": 3, "componentType": 5123, "count": 6, "type": "SCALAR"},
]
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
    "images": [{"name": "diffuse", "mimeType": "image/png", "uri": uri(png([255, 200, 150, 90, 160, 220], 2, 3), "image/png")},
               {"name": "specular glossiness", "mimeType": "image/png",
                "uri": uri(png([200, 150, 100, 255, 60, 60, 60, 64], 2, 4), "image/png")}],
    "accessors": acc, "bufferViews": bv,
    "buffers": [{"byteLength": len(buf), "uri": uri(buf, "application/octet-stream")}],
}
open("specular_glossiness_quad.gltf", "w").write(json.dumps(doc, indent=1) + "\n")
