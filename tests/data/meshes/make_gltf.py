#!/usr/bin/env python3
"""Writes two_materials.gltf and two_materials.glb (test data): the unit square of
two_materials.obj as two triangles, grass and asphalt, in glTF's Y-up frame (glTF 2.0
section 3.4: +Y up, metres), so that sigchain's Z-up rule turns (x, y, z) into
(x, -z, y) and gives back the square at z = 0.  Run from this folder: python3 make_gltf.py"""
import base64
import json
import struct

# Z-up square corners (x, y, 0) stored Y-up as (x, 0, -y).
corners = [(0, 0), (1, 0), (1, 1), (0, 1)]
positions = b"".join(struct.pack("<3f", x, 0.0, -y) for x, y in corners)
triangles = [(0, 1, 2), (0, 2, 3)]
indices = [struct.pack("<3H", *t) for t in triangles]  # 6 bytes each
data = positions + indices[0] + indices[1]


def document(buffer):
    return {
        "asset": {"version": "2.0", "generator": "sigchain tests/data/meshes/make_gltf.py"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"name": "square", "mesh": 0}],
        "meshes": [{"name": "square", "primitives": [
            {"attributes": {"POSITION": 0}, "indices": 1, "material": 0},
            {"attributes": {"POSITION": 0}, "indices": 2, "material": 1}]}],
        "materials": [{"name": "grass"}, {"name": "asphalt"}],
        "buffers": [buffer],
        "bufferViews": [
            {"buffer": 0, "byteOffset": 0, "byteLength": 48},
            {"buffer": 0, "byteOffset": 48, "byteLength": 6},
            {"buffer": 0, "byteOffset": 54, "byteLength": 6}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
             "min": [0, 0, -1], "max": [1, 0, 0]},
            {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"},
            {"bufferView": 2, "componentType": 5123, "count": 3, "type": "SCALAR"}],
    }


uri = "data:application/octet-stream;base64," + base64.b64encode(data).decode()
with open("two_materials.gltf", "w") as f:
    json.dump(document({"byteLength": len(data), "uri": uri}), f, indent=1)
    f.write("\n")

# GLB (glTF 2.0 section 4.4): header, a JSON chunk padded with spaces, a BIN chunk
# padded with zeros, each to 4 bytes.
text = json.dumps(document({"byteLength": len(data)})).encode()
text += b" " * (-len(text) % 4)
binary = data + b"\0" * (-len(data) % 4)
chunks = struct.pack("<I4s", len(text), b"JSON") + text + struct.pack("<I4s", len(binary), b"BIN\0") + binary
with open("two_materials.glb", "wb") as f:
    f.write(struct.pack("<4sII", b"glTF", 2, 12 + len(chunks)) + chunks)
