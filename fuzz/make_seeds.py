#!/usr/bin/env python3
"""Writes the hand-made seed files of the fuzzers (fuzz/seeds/) and the files fuzzed glTF and
scene files may name (fuzz/files/). Run once; the outputs are committed. The JPEGs
(files/texture.jpg, seeds/texture/*.jpg) were written with stb_image_write (stbi_write_jpg: 8x8 RGB
at quality 80 and 50, 16x4 grey at 90). Each is a small valid
file of its format; scripts/fuzz.sh adds the real ones from ../shared/assets."""
import base64, json, os, struct, zlib

ROOT = os.path.dirname(os.path.abspath(__file__))

def write(path, data):
    path = os.path.join(ROOT, path)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "wb") as f:
        f.write(data if isinstance(data, bytes) else data.encode())

def png(width, height, pixels, colour_type=6, depth=8):
    """pixels: bytes of one row after another, without filter bytes."""
    channels = {0: 1, 2: 3, 4: 2, 6: 4}[colour_type]
    stride = width * channels * depth // 8
    raw = b"".join(b"\0" + pixels[y * stride:(y + 1) * stride] for y in range(height))
    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body) & 0xffffffff)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, depth, colour_type, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))

rgba = png(4, 4, bytes((x * 60, y * 60, 128, 255) [c] for y in range(4) for x in range(4) for c in range(4)))
grey16 = png(2, 2, struct.pack(">4H", 0, 0x4040, 0x8080, 0xffff), colour_type=0, depth=16)
rgb = png(3, 1, bytes([255, 0, 0, 0, 255, 0, 0, 0, 255]), colour_type=2)

# A triangle: three float3 positions, three float3 normals, three float2 uvs, three uint16 indices.
positions = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0)
normals = struct.pack("<9f", 0, 0, 1, 0, 0, 1, 0, 0, 1)
uvs = struct.pack("<6f", 0, 0, 1, 0, 0, 1)
indices = struct.pack("<3H", 0, 1, 2) + b"\0\0"
buffer = positions + normals + uvs + indices

def triangle_gltf(buffer_uri, image):
    return {
        "asset": {"version": "2.0"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0, "children": [1], "rotation": [0, 0, 0, 1]},
                  {"camera": 0, "translation": [0, 0, 3], "extensions": {"KHR_lights_punctual": {"light": 0}}}],
        "cameras": [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1, "zfar": 100}}],
        "extensionsUsed": ["KHR_lights_punctual", "KHR_texture_transform"],
        "extensions": {"KHR_lights_punctual": {"lights": [{"type": "spot", "intensity": 10, "spot": {"outerConeAngle": 0.5}}]}},
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}, "indices": 3, "material": 0}]}],
        "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0, "extensions": {"KHR_texture_transform": {"scale": [2, 2]}}},
                                                "metallicFactor": 0.5, "roughnessFactor": 0.5},
                       "normalTexture": {"index": 0}, "alphaMode": "MASK", "doubleSided": True}],
        "textures": [{"source": 0, "sampler": 0}],
        "samplers": [{"magFilter": 9728, "minFilter": 9987, "wrapS": 33071}],
        "images": [image],
        "buffers": [{"uri": buffer_uri, "byteLength": len(buffer)}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36},
                        {"buffer": 0, "byteOffset": 36, "byteLength": 36},
                        {"buffer": 0, "byteOffset": 72, "byteLength": 24},
                        {"buffer": 0, "byteOffset": 96, "byteLength": 6}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
                      {"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC3"},
                      {"bufferView": 2, "componentType": 5126, "count": 3, "type": "VEC2"},
                      {"bufferView": 3, "componentType": 5123, "count": 3, "type": "SCALAR"}],
    }

write("files/buffer.bin", buffer)
write("files/texture.png", rgba)
write("files/model.gltf", json.dumps(triangle_gltf("buffer.bin", {"uri": "texture.png"})))

write("seeds/gltf/triangle.gltf", json.dumps(triangle_gltf("buffer.bin", {"uri": "texture.png"}), indent=1))
datauri = triangle_gltf("data:application/octet-stream;base64," + base64.b64encode(buffer).decode(),
                        {"uri": "data:image/png;base64," + base64.b64encode(grey16).decode()})
write("seeds/gltf/datauri.gltf", json.dumps(datauri))
sparse = triangle_gltf("buffer.bin", {"uri": "texture.jpg"})
sparse["accessors"].append({"componentType": 5126, "count": 3, "type": "VEC3",
                            "sparse": {"count": 1, "indices": {"bufferView": 3, "componentType": 5123},
                                       "values": {"bufferView": 0}}})
sparse["meshes"][0]["primitives"].append({"attributes": {"POSITION": 4}, "mode": 5})
write("seeds/gltf/sparse.gltf", json.dumps(sparse))
# KHR_materials_sheen: factors and both textures, one through texCoord 1 and a transform.
sheen = triangle_gltf("buffer.bin", {"uri": "texture.png"})
sheen["extensionsUsed"].append("KHR_materials_sheen")
sheen["materials"][0]["extensions"] = {"KHR_materials_sheen": {
    "sheenColorFactor": [1, 0.5, 0.2], "sheenRoughnessFactor": 0.4,
    "sheenColorTexture": {"index": 0, "texCoord": 1, "extensions": {"KHR_texture_transform": {"offset": [0.5, 0]}}},
    "sheenRoughnessTexture": {"index": 0}}}
write("seeds/gltf/sheen.gltf", json.dumps(sheen))
# KHR_materials_anisotropy: strength, rotation and a texture with texCoord and a transform, no
# normal map (so the importer makes the tangents for it).
anisotropy = triangle_gltf("buffer.bin", {"uri": "texture.png"})
del anisotropy["materials"][0]["normalTexture"]
anisotropy["materials"][0]["extensions"] = {"KHR_materials_anisotropy": {
    "anisotropyStrength": 0.8, "anisotropyRotation": 1.2,
    "anisotropyTexture": {"index": 0, "texCoord": 0, "extensions": {"KHR_texture_transform": {"rotation": 0.5}}}}}
anisotropy["extensionsUsed"].append("KHR_materials_anisotropy")
write("seeds/gltf/anisotropy.gltf", json.dumps(anisotropy, indent=1))
# KHR_materials_iridescence: factor, film IOR, thickness range, both textures (one with a texCoord
# and a KHR_texture_transform), so the fuzzer reaches the extension's importer.
iridescence = triangle_gltf("buffer.bin", {"uri": "texture.png"})
iridescence["extensionsUsed"].append("KHR_materials_iridescence")
iridescence["materials"][0]["extensions"] = {"KHR_materials_iridescence": {
    "iridescenceFactor": 0.8, "iridescenceTexture": {"index": 0}, "iridescenceIor": 1.6,
    "iridescenceThicknessMinimum": 150, "iridescenceThicknessMaximum": 650,
    "iridescenceThicknessTexture": {"index": 0, "texCoord": 0, "extensions": {"KHR_texture_transform": {"offset": [0.5, 0], "scale": [-1, 1]}}}}}
write("seeds/gltf/iridescence.gltf", json.dumps(iridescence))
# KHR_materials_specular's, _transmission's, _volume's and _diffuse_transmission's textures;
# EXT_mesh_gpu_instancing (three instances from the triangle's own VEC3 accessors) and
# KHR_node_visibility on the camera's node.
textured = triangle_gltf("buffer.bin", {"uri": "texture.png"})
textured["extensionsUsed"] += ["KHR_materials_specular", "KHR_materials_transmission", "KHR_materials_volume",
                               "KHR_materials_diffuse_transmission", "EXT_mesh_gpu_instancing", "KHR_node_visibility"]
textured["materials"][0]["extensions"] = {
    "KHR_materials_specular": {"specularFactor": 0.5, "specularTexture": {"index": 0},
                               "specularColorFactor": [1, 0.5, 0.2], "specularColorTexture": {"index": 0, "texCoord": 1}},
    "KHR_materials_transmission": {"transmissionFactor": 0.7, "transmissionTexture": {"index": 0}},
    "KHR_materials_volume": {"thicknessFactor": 0.2, "thicknessTexture": {"index": 0, "extensions": {"KHR_texture_transform": {"offset": [0.5, 0]}}}},
    "KHR_materials_diffuse_transmission": {"diffuseTransmissionFactor": 0.6, "diffuseTransmissionTexture": {"index": 0},
                                           "diffuseTransmissionColorFactor": [1, 0.9, 0.3],
                                           "diffuseTransmissionColorTexture": {"index": 0, "texCoord": 1}}}
textured["nodes"][0]["extensions"] = {"EXT_mesh_gpu_instancing": {"attributes": {"TRANSLATION": 0, "SCALE": 1}}}
textured["nodes"][1]["extensions"]["KHR_node_visibility"] = {"visible": False}
write("seeds/gltf/textured_instanced.gltf", json.dumps(textured))
# KHR_animation_pointer: channels on a texture transform's offset, the emissive factor, the
# light's intensity, the alpha cutoff and a node's KHR_node_visibility (unsigned bytes, STEP),
# keyframes read from the positions (times 0, 1 from its third float on).
pointers = triangle_gltf("buffer.bin", {"uri": "texture.png"})
pointers["extensionsUsed"].append("KHR_animation_pointer")
pointers["accessors"] += [{"bufferView": 0, "byteOffset": 8, "componentType": 5126, "count": 2, "type": "SCALAR"},
                          {"bufferView": 0, "componentType": 5126, "count": 2, "type": "VEC2"},
                          {"bufferView": 0, "componentType": 5126, "count": 2, "type": "VEC3"},
                          {"bufferView": 0, "componentType": 5121, "count": 2, "type": "SCALAR"}]
def pointer_channel(sampler, path):
    return {"sampler": sampler, "target": {"path": "pointer", "extensions": {"KHR_animation_pointer": {"pointer": path}}}}
pointers["animations"] = [{"samplers": [{"input": 4, "output": 5, "interpolation": "STEP"},
                                        {"input": 4, "output": 6, "interpolation": "LINEAR"},
                                        {"input": 4, "output": 4, "interpolation": "LINEAR"},
                                        {"input": 4, "output": 7, "interpolation": "STEP"}],
                           "channels": [pointer_channel(0, "/materials/0/pbrMetallicRoughness/baseColorTexture/extensions/KHR_texture_transform/offset"),
                                        pointer_channel(1, "/materials/0/emissiveFactor"),
                                        pointer_channel(2, "/extensions/KHR_lights_punctual/lights/0/intensity"),
                                        pointer_channel(2, "/materials/0/alphaCutoff"),
                                        pointer_channel(3, "/nodes/0/extensions/KHR_node_visibility/visible")]}]
write("seeds/gltf/animation_pointer.gltf", json.dumps(pointers))
# Points and lines: the triangle as a LINE_LOOP (indexed), a LINE_STRIP and POINTS (non-indexed,
# no normals: drawn unlit).
modes = triangle_gltf("buffer.bin", {"uri": "texture.png"})
modes["meshes"][0]["primitives"] = [
    {"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}, "indices": 3, "material": 0, "mode": 2},
    {"attributes": {"POSITION": 0}, "mode": 3},
    {"attributes": {"POSITION": 0, "TEXCOORD_0": 2}, "material": 0, "mode": 0}]
write("seeds/gltf/primitive_modes.gltf", json.dumps(modes))
# The archived KHR_materials_pbrSpecularGlossiness, converted on import.
specgloss = triangle_gltf("buffer.bin", {"uri": "texture.png"})
specgloss["extensionsUsed"].append("KHR_materials_pbrSpecularGlossiness")
specgloss["materials"][0]["extensions"] = {"KHR_materials_pbrSpecularGlossiness": {
    "diffuseFactor": [1, 0.8, 0.6, 1], "diffuseTexture": {"index": 0}, "specularFactor": [0.5, 0.5, 0.5],
    "glossinessFactor": 0.7, "specularGlossinessTexture": {"index": 0}}}
write("seeds/gltf/specular_glossiness.gltf", json.dumps(specgloss))

def glb(document, binary):
    text = json.dumps(document).encode()
    text += b" " * (-len(text) % 4)
    binary += b"\0" * (-len(binary) % 4)
    body = struct.pack("<II", len(text), 0x4E4F534A) + text + struct.pack("<II", len(binary), 0x004E4942) + binary
    return struct.pack("<III", 0x46546C67, 2, 12 + len(body)) + body

embedded = triangle_gltf(None, {"bufferView": 4, "mimeType": "image/png"})
del embedded["buffers"][0]["uri"]
embedded["buffers"][0]["byteLength"] = len(buffer) + len(rgba)
embedded["bufferViews"].append({"buffer": 0, "byteOffset": len(buffer), "byteLength": len(rgba)})
write("seeds/glb/triangle.glb", glb(embedded, buffer + rgba))

write("seeds/texture/rgba.png", rgba)
write("seeds/texture/grey16.png", grey16)
write("seeds/texture/rgb.png", rgb)

def hdr(width, height, rle):
    head = b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\nEXPOSURE=1.0\n\n" + f"-Y {height} +X {width}\n".encode()
    body = b""
    for y in range(height):
        if rle:
            body += bytes([2, 2, width >> 8, width & 255])
            for channel in range(4):
                value = [128, 64 + y, 32, 129][channel]
                body += bytes([128 + width // 2, value])          # a run
                body += bytes([width - width // 2]) + bytes(range(width - width // 2))  # a dump
        else:
            body += b"".join(bytes([x * 30, y * 30, 100, 128]) for x in range(width))
    return head + body

write("seeds/hdr/rle.hdr", hdr(16, 3, True))
write("seeds/hdr/flat.hdr", hdr(4, 2, False))
# seeds/hdr/nul-header-line.hdr is not made here: fuzz_hdr's finding of 2026-12-03, kept as it was found
# (tests/unit/test_image_io.cpp, HdrWhoseHeaderEndsWithANulLineIsWalkedAsStbImageReadsIt).
write("files/env.hdr", hdr(16, 8, True))

def exr(width, height):
    """Scanline, uncompressed, half B, G, R."""
    def attr(name, kind, value):
        return name.encode() + b"\0" + kind.encode() + b"\0" + struct.pack("<i", len(value)) + value
    channels = b"".join(c + b"\0" + struct.pack("<iBBBBii", 1, 0, 0, 0, 0, 1, 1) for c in (b"B", b"G", b"R")) + b"\0"
    header = (struct.pack("<II", 20000630, 2) + attr("channels", "chlist", channels)
              + attr("compression", "compression", b"\0")
              + attr("dataWindow", "box2i", struct.pack("<4i", 0, 0, width - 1, height - 1))
              + attr("displayWindow", "box2i", struct.pack("<4i", 0, 0, width - 1, height - 1))
              + attr("lineOrder", "lineOrder", b"\0") + attr("pixelAspectRatio", "float", struct.pack("<f", 1))
              + attr("screenWindowCenter", "v2f", struct.pack("<2f", 0, 0)) + attr("screenWindowWidth", "float", struct.pack("<f", 1))
              + b"\0")
    line = width * 3 * 2
    first = len(header) + 8 * height
    offsets = b"".join(struct.pack("<Q", first + y * (8 + line)) for y in range(height))
    one = struct.pack("<e", 1.0)
    lines = b"".join(struct.pack("<ii", y, line) + one * (width * 3) for y in range(height))
    return header + offsets + lines

write("seeds/exr/small.exr", exr(4, 3))

write("seeds/scene/all.json", json.dumps({
    "models": [{"path": "model.gltf", "position": [0, 0, 0], "scale": 2, "name": "m", "castShadows": False,
                "materials": {"*": {"roughness": 0.3}}}],
    "shapes": [{"type": "sphere", "radius": 1, "segments": 8, "rings": 4, "material": {"baseColor": [1, 0, 0], "metallic": 1}},
               {"type": "plane", "size": 1, "material": {"doubleSided": True, "diffuseTransmission": 0.5, "diffuseTransmissionColor": [1, 0.5, 0]}},
               {"type": "box", "halfExtent": [1, 2, 3]}, {"type": "plane", "size": 10, "uvRepeat": 2}],
    "lights": [{"type": "point", "position": [0, 3, 0], "intensity": 100, "color": [1, 1, 1], "range": 10},
               {"type": "spot", "position": [0, 3, 0], "target": [0, 0, 0], "innerConeAngle": 0.2, "outerConeAngle": 0.4},
               {"type": "directional", "direction": [0, -1, 0], "angularDiameter": 0.5, "castShadows": True}],
    "billboards": [{"kind": "axis-aligned", "image": "texture.png", "size": [1, 2], "position": [0, 0, 0], "scatter": {"count": 4}}],
    "camera": {"type": "perspective", "position": [0, 1, 5], "target": [0, 0, 0], "yfov": 45, "aperture": 2.8, "shutter": 0.01, "iso": 100},
    "environment": {"file": "env.hdr", "intensity": 1.5, "rotation": 90},
    "render": {"width": 64, "height": 32, "msaa": 4, "exposure": 0.5, "tonemap": "aces"},
    "post": {"bloom": {"enabled": True, "intensity": 0.1}, "ssao": {"enabled": True}},
}, indent=1))

for name, args in {
    "render": ["render", "demo", "-o", "out.png", "--width", "64", "--height", "32", "--exposure", "1.5", "--msaa", "2",
               "--tonemap", "aces", "--bloom", "on", "--bloom-intensity", "0.2", "--env-color", "1,2,3", "--skybox", "blur=0.5"],
    "limits": ["render", "x.gltf", "--max-image-size", "64", "--max-texture-memory", "16MiB", "--max-buffer-bytes", "1GB",
               "--max-accessor-count", "1000", "--allow-external-files"],
    "view": ["view", "--frames", "2", "--screenshot", "a.png", "--shading", "doom", "--ev100", "12", "--shadow-filter", "pcss"],
    "bench": ["bench", "--scene", "demo", "learnopengl", "--frames", "3", "--warmup", "1", "--env-intensity", "2", "--env-rotation", "30"],
    "gallery": ["gallery", "--variants", "--columns", "2", "--brdf-d", "beckmann", "--debug-view", "normal"],
}.items():
    write(f"seeds/cli/{name}.txt", "\n".join(args))
