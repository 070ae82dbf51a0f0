# Writes sheen_quad.gltf (run in this directory; the output is committed).
# One 2 x 2 quad facing +Z (normals +Z), a rough dark blue dielectric under KHR_materials_sheen
# whose colour and roughness come from textures, so that every texel is known exactly
# (tests/gl/test_sheen.cpp):
#   sheenColorFactor (0.9, 1, 0.8) x sheenColorTexture, a 2 x 1 sRGB PNG: texel 0 (255, 128, 64),
#   texel 1 (64, 160, 255), sampled NEAREST with REPEAT through texCoord 1 (u1 = 1 - u0, v1 = v0)
#   and KHR_texture_transform offset (0.5, 0): texel 0 on the quad's left half (x < 0), texel 1
#   on its right; either the transform or the texCoord alone would swap them.
#   sheenRoughnessFactor 0.8 x sheenRoughnessTexture A 153/255 (a 1 x 1 RGBA PNG, RGB unused).
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
uv1 = [1, 1, 0, 1, 0, 0, 1, 0]
idx = [0, 1, 2, 0, 2, 3]
def pack(fmt, v): return struct.pack("<%d%s" % (len(v), fmt), *v)
views = [pack("f", pos), pack("f", nrm), pack("f", uv0), pack("f", uv1), pack("H", idx)]
buf = b""; bv = []
for k, v in enumerate(views):
    while len(buf) % 4: buf += b"\0"
    bv.append({"buffer": 0, "byteOffset": len(buf), "byteLength": len(v), "target": 34963 if k == 4 else 34962}); buf += v
acc = [
    {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [-1, -1, 0], "max": [1, 1, 0]},
    {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC3"},
    {"bufferView": 2, "componentType": 5126, "count": 4, "type": "VEC2"},
    {"bufferView": 3, "componentType": 5126, "count": 4, "type": "VEC2"},
    {"bufferView": 4, "componentType": 5123, "count": 6, "type": "SCALAR"},
]
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
    "images": [{"name": "sheen colour", "mimeType": "image/png", "uri": uri(png([255, 128, 64, 64, 160, 255], 2, 3), "image/png")},
               {"name": "sheen roughness", "mimeType": "image/png", "uri": uri(png([0, 0, 0, 153], 1, 4), "image/png")}],
    "accessors": acc, "bufferViews": bv,
    "buffers": [{"byteLength": len(buf), "uri": uri(buf, "application/octet-stream")}],
}
open("sheen_quad.gltf", "w").write(json.dumps(doc, indent=1) + "\n")
