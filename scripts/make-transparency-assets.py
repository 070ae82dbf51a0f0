#!/usr/bin/env python3
"""Writes the transparency test assets (tests/assets/transparency/): small glTF files with
KHR_materials_transmission, KHR_materials_ior and KHR_materials_volume, their buffers embedded.
Run from the repository root; validate with npm's gltf-validator (docs/transparency.md)."""
import base64
import json
import struct
from pathlib import Path

OUT = Path("tests/assets/transparency")


def cube(half):
    """24 vertices (a face's own normals), 36 indices, counter-clockwise seen from outside."""
    positions, normals, indices = [], [], []
    for axis in range(3):
        for sign in (1.0, -1.0):
            n = [0.0, 0.0, 0.0]
            n[axis] = sign
            u = [0.0, 0.0, 0.0]
            v = [0.0, 0.0, 0.0]
            u[(axis + 1) % 3] = 1.0
            v[(axis + 2) % 3] = 1.0
            if sign < 0:
                u, v = v, u
            base = len(positions)
            for a, b in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
                positions.append([half * (n[i] + a * u[i] + b * v[i]) for i in range(3)])
                normals.append(n)
            indices += [base, base + 1, base + 2, base, base + 2, base + 3]
    return positions, normals, indices


def quad(half):
    """A square in the XY plane facing +Z."""
    positions = [[-half, -half, 0.0], [half, -half, 0.0], [half, half, 0.0], [-half, half, 0.0]]
    normals = [[0.0, 0.0, 1.0]] * 4
    return positions, normals, [0, 1, 2, 0, 2, 3]


def gltf(name, mesh, material, extensions):
    positions, normals, indices = mesh
    blob = b"".join(struct.pack("<3f", *p) for p in positions)
    blob += b"".join(struct.pack("<3f", *n) for n in normals)
    index_offset = len(blob)
    blob += b"".join(struct.pack("<H", i) for i in indices)
    while len(blob) % 4:
        blob += b"\0"
    count = len(positions)
    lo = [min(p[i] for p in positions) for i in range(3)]
    hi = [max(p[i] for p in positions) for i in range(3)]
    return {
        "asset": {"version": "2.0", "generator": "Specula scripts/make-transparency-assets.py"},
        "extensionsUsed": extensions,
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"name": name, "mesh": 0}],
        "meshes": [{"name": name, "primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 2, "material": 0}]}],
        "materials": [material],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": count, "type": "VEC3", "min": lo, "max": hi},
            {"bufferView": 0, "byteOffset": 12 * count, "componentType": 5126, "count": count, "type": "VEC3"},
            {"bufferView": 1, "componentType": 5123, "count": len(indices), "type": "SCALAR"},
        ],
        "bufferViews": [
            {"buffer": 0, "byteOffset": 0, "byteLength": 24 * count, "byteStride": 12, "target": 34962},
            {"buffer": 0, "byteOffset": index_offset, "byteLength": 2 * len(indices), "target": 34963},
        ],
        "buffers": [{"byteLength": len(blob), "uri": "data:application/octet-stream;base64," + base64.b64encode(blob).decode()}],
    }


def write(file, document):
    (OUT / file).write_text(json.dumps(document, indent=1) + "\n")


def main():
    OUT.mkdir(parents=True, exist_ok=True)
    # A volume of amber glass: 1 m cube, its thickness 1 m, light keeping [0.9, 0.6, 0.3] per 0.5 m.
    write("GlassBox.gltf", gltf("glass box", cube(0.5), {
        "name": "amber glass",
        "pbrMetallicRoughness": {"baseColorFactor": [1, 1, 1, 1], "metallicFactor": 0.0, "roughnessFactor": 0.05},
        "extensions": {
            "KHR_materials_transmission": {"transmissionFactor": 1.0},
            "KHR_materials_ior": {"ior": 1.5},
            "KHR_materials_volume": {"thicknessFactor": 1.0, "attenuationDistance": 0.5,
                                     "attenuationColor": [0.9, 0.6, 0.3]},
        },
    }, ["KHR_materials_transmission", "KHR_materials_ior", "KHR_materials_volume"]))
    # A thin-walled pane (no volume) of frosted glass, ior 1.33 (water), 70 % transmissive.
    write("FrostedPane.gltf", gltf("frosted pane", quad(0.5), {
        "name": "frosted",
        "doubleSided": True,
        "pbrMetallicRoughness": {"baseColorFactor": [0.9, 0.95, 1.0, 1], "metallicFactor": 0.0, "roughnessFactor": 0.4},
        "extensions": {
            "KHR_materials_transmission": {"transmissionFactor": 0.7},
            "KHR_materials_ior": {"ior": 1.33},
        },
    }, ["KHR_materials_transmission", "KHR_materials_ior"]))


if __name__ == "__main__":
    main()
