# Writes anisotropy_plate.gltf (run in this directory; the output is committed).
# A brushed-metal plate: one 2 x 2 quad facing +Z (normals +Z, tangents +X, so the tangent
# frame is the world's x, y), a rough grey metal with KHR_materials_anisotropy whose direction
# and strength come from an 8 x 8 PNG (linear, nearest filtering, so every texel is known
# exactly: tests/gl/test_anisotropy.cpp): concentric brushing, each texel's RG the circle's
# direction around the plate's centre (x 0.5 + 0.5), B the strength, 0.4 at the centre to 1 at
# the corners; anisotropyStrength 0.9 scales it and anisotropyRotation 0.25 rad turns it.
import json, math

from quad import png, quad, uri

N = 8

def byte(x):
    return max(0, min(255, int(round(x * 255.0))))

rows = []
for j in range(N):
    row = []
    for i in range(N):
        # The texel's centre on the plate: uv (0, 1) is the corner (-1, -1), uv (1, 0) is (1, 1).
        x = 2.0 * (i + 0.5) / N - 1.0
        y = 1.0 - 2.0 * (j + 0.5) / N
        r = math.hypot(x, y)
        dx, dy = -y / r, x / r  # along the circle, counter-clockwise
        strength = 0.4 + 0.6 * r / math.sqrt(2.0)
        row += [byte(dx * 0.5 + 0.5), byte(dy * 0.5 + 0.5), byte(strength)]
    rows.append(row)

buf, bv, acc = quad(tangents=True, uv1=False)
doc = {
    "asset": {"version": "2.0", "generator": "Specula tests/assets/gltf/make_anisotropy.py"},
    "extensionsUsed": ["KHR_materials_anisotropy"],
    "scene": 0, "scenes": [{"nodes": [0]}],
    "nodes": [{"mesh": 0, "name": "plate"}],
    "meshes": [{"name": "plate", "primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TANGENT": 2, "TEXCOORD_0": 3},
                                                  "indices": 4, "material": 0}]}],
    "materials": [{
        "name": "brushed metal",
        "pbrMetallicRoughness": {"baseColorFactor": [0.9, 0.9, 0.92, 1.0], "metallicFactor": 1.0, "roughnessFactor": 0.35},
        "extensions": {"KHR_materials_anisotropy": {
            "anisotropyStrength": 0.9, "anisotropyRotation": 0.25, "anisotropyTexture": {"index": 0}}}}],
    "samplers": [{"magFilter": 9728, "minFilter": 9728}],
    "textures": [{"source": 0, "sampler": 0}],
    "images": [{"name": "brushing", "mimeType": "image/png", "uri": uri(png(N, N, rows, level=9), "image/png")}],
    "accessors": acc, "bufferViews": bv,
    "buffers": [{"byteLength": len(buf), "uri": uri(buf, "application/octet-stream")}],
}
open("anisotropy_plate.gltf", "w").write(json.dumps(doc, indent=1) + "\n")
