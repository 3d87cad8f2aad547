#!/usr/bin/env python3
"""Writes the KHR material-extension test assets beside this script: one UV
sphere per extension (clearcoat, sheen, specular, ior), each a self-contained
.gltf (buffers and PNGs as data: URIs). The extension textures hold their
value in the channel the extension reads and 0 elsewhere, so reading the
wrong channel loses the effect. Run it again after changing it:
    python3 tests/assets/khr-materials/make_assets.py
"""
import base64, json, math, os, struct, zlib

HERE = os.path.dirname(os.path.abspath(__file__))


def png(rgba, size=4):
    raw = b"".join(b"\0" + bytes(rgba) * size for _ in range(size))
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", size, size, 8, 6, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))


def sphere(segments=48, rings=24):
    positions, normals, uvs, indices = [], [], [], []
    for j in range(rings + 1):
        v = j / rings
        theta = v * math.pi
        for i in range(segments + 1):
            u = i / segments
            phi = u * 2 * math.pi
            n = (math.sin(theta) * math.sin(phi), math.cos(theta), math.sin(theta) * math.cos(phi))
            positions.append(n)
            normals.append(n)
            uvs.append((u, v))
    for j in range(rings):
        for i in range(segments):
            a, b = j * (segments + 1) + i, (j + 1) * (segments + 1) + i
            if j > 0:
                indices += [a, b, a + 1]
            if j < rings - 1:
                indices += [a + 1, b, b + 1]
    return positions, normals, uvs, indices


def asset(name, material, extensions, textures):
    positions, normals, uvs, indices = sphere()
    blob = b"".join(struct.pack("<3f", *p) for p in positions)
    blob += b"".join(struct.pack("<3f", *n) for n in normals)
    blob += b"".join(struct.pack("<2f", *t) for t in uvs)
    index_offset = len(blob)
    blob += struct.pack("<%dH" % len(indices), *indices)
    count = len(positions)
    doc = {
        "asset": {"version": "2.0", "generator": "tests/assets/khr-materials/make_assets.py"},
        "extensionsUsed": sorted(extensions + ["KHR_lights_punctual"]),
        "extensionsRequired": sorted(extensions),
        "scene": 0,
        "scenes": [{"nodes": [0, 1, 2]}],
        "nodes": [
            {"name": name, "mesh": 0},
            {"name": "camera", "camera": 0, "translation": [0, 0, 3.4]},
            # A sun from the upper left, in front: the highlight sits up and left of the centre.
            {"name": "sun", "rotation": [-0.2705981, -0.2705981, 0.0, 0.9238795],
             "extensions": {"KHR_lights_punctual": {"light": 0}}},
        ],
        "cameras": [{"type": "perspective", "perspective": {"yfov": 0.7, "znear": 0.1, "zfar": 20, "aspectRatio": 1}}],
        "extensions": {"KHR_lights_punctual": {"lights": [{"type": "directional", "intensity": 3.0}]}},
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}, "indices": 3,
                                    "material": 0}]}],
        "materials": [material],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": count, "type": "VEC3", "min": [-1, -1, -1], "max": [1, 1, 1]},
            {"bufferView": 0, "byteOffset": count * 12, "componentType": 5126, "count": count, "type": "VEC3"},
            {"bufferView": 0, "byteOffset": count * 24, "componentType": 5126, "count": count, "type": "VEC2"},
            {"bufferView": 1, "componentType": 5123, "count": len(indices), "type": "SCALAR"},
        ],
        "bufferViews": [{"buffer": 0, "byteLength": index_offset},
                        {"buffer": 0, "byteOffset": index_offset, "byteLength": len(indices) * 2}],
        "buffers": [{"byteLength": len(blob),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(blob).decode()}],
    }
    if textures:
        doc["images"] = [{"uri": "data:image/png;base64," + base64.b64encode(png(t)).decode()} for t in textures]
        doc["textures"] = [{"source": i} for i in range(len(textures))]
    with open(os.path.join(HERE, name + ".gltf"), "w") as f:
        json.dump(doc, f, indent=1)
        f.write("\n")


# A rough orange dielectric under a smooth coat: the coat adds a sharp highlight.
asset("clearcoat", {
    "name": "coated",
    "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.25, 0.05, 1], "metallicFactor": 0.0, "roughnessFactor": 0.7},
    "extensions": {"KHR_materials_clearcoat": {
        "clearcoatFactor": 1.0, "clearcoatTexture": {"index": 0},
        "clearcoatRoughnessFactor": 0.3, "clearcoatRoughnessTexture": {"index": 1},
        "clearcoatNormalTexture": {"index": 2, "scale": 1.0}}},
}, ["KHR_materials_clearcoat"], [(255, 0, 0, 255), (0, 85, 0, 255), (128, 128, 255, 255)])  # roughness 0.3 x 1/3

# A dark blue cloth with a bright sheen: the grazing rim lights up.
asset("sheen", {
    "name": "velvet",
    "pbrMetallicRoughness": {"baseColorFactor": [0.02, 0.03, 0.12, 1], "metallicFactor": 0.0, "roughnessFactor": 0.9},
    "extensions": {"KHR_materials_sheen": {
        "sheenColorFactor": [1.0, 0.9, 0.8], "sheenColorTexture": {"index": 0},
        "sheenRoughnessFactor": 0.5, "sheenRoughnessTexture": {"index": 1}}},
}, ["KHR_materials_sheen"], [(255, 255, 255, 255), (0, 0, 0, 255)])  # roughness 0.5 x 1 (alpha)

# A grey dielectric whose reflections are tinted orange: f0 = 0.04 x (6, 2, 0.25).
asset("specular", {
    "name": "tinted",
    "pbrMetallicRoughness": {"baseColorFactor": [0.3, 0.3, 0.3, 1], "metallicFactor": 0.0, "roughnessFactor": 0.3},
    "extensions": {"KHR_materials_specular": {
        "specularFactor": 1.0, "specularTexture": {"index": 0},
        "specularColorFactor": [6.0, 2.0, 0.25], "specularColorTexture": {"index": 1}}},
}, ["KHR_materials_specular"], [(0, 0, 0, 255), (255, 255, 255, 255)])  # specular 1 x 1 (alpha)

# A diamond-like index: f0 = ((2.4 - 1) / 3.4)^2 = 0.17, four times glTF's 0.04.
asset("ior", {
    "name": "gem",
    "pbrMetallicRoughness": {"baseColorFactor": [0.1, 0.3, 0.1, 1], "metallicFactor": 0.0, "roughnessFactor": 0.25},
    "extensions": {"KHR_materials_ior": {"ior": 2.4}},
}, ["KHR_materials_ior"], [])
