#!/usr/bin/env python3
"""Writes tests/validator/hostile: small sample models (tools/gltf_minimize.py)
with one hostile change each: references out of range or wrapping at 2^31 and
2^32, accessor and buffer-view bounds, counts, sparse data, index values,
transforms, cameras, materials, buffers, JSON syntax and GLB containers.
Deterministic (fixed models, fixed order, seeded sampling); the differential
test (tests/validator) runs the Khronos glTF-Validator and the loader over it.
Rerun after changing this script and commit the result."""
import copy
import json
import os
import random
import shutil
import struct
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gltf_minimize as gm  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ASSETS = os.path.join(ROOT, "..", "shared", "assets", "gltf")
OUT = os.path.join(ROOT, "tests", "validator", "hostile")
MODELS = ["Triangle", "Box", "SimpleSparseAccessor", "Cameras", "BoxTextured", "TextureTransformTest"]
PER_MODEL_REFERENCES = 6  # sampled reference mutations per model (all four values each)
PER_MODEL_OBJECTS = 2  # accessors, buffer views, primitives, cameras, materials mutated per model

# Where the document refers to another object: (JSON path pattern, collection).
REFERENCES = [
    (("scene",), "scenes"), (("scenes", "*", "nodes", "*"), "nodes"), (("nodes", "*", "children", "*"), "nodes"),
    (("nodes", "*", "mesh"), "meshes"), (("nodes", "*", "camera"), "cameras"),
    (("meshes", "*", "primitives", "*", "attributes", "*"), "accessors"),
    (("meshes", "*", "primitives", "*", "indices"), "accessors"),
    (("meshes", "*", "primitives", "*", "material"), "materials"),
    (("accessors", "*", "bufferView"), "bufferViews"),
    (("accessors", "*", "sparse", "indices", "bufferView"), "bufferViews"),
    (("accessors", "*", "sparse", "values", "bufferView"), "bufferViews"),
    (("bufferViews", "*", "buffer"), "buffers"), (("textures", "*", "source"), "images"),
    (("textures", "*", "sampler"), "samplers"), (("materials", "*", "**", "index"), "textures"),
]


def walk(node, pattern, path=()):
    """Every (path, value) under node that matches pattern ('*' one key, '**' any depth)."""
    if not pattern:
        yield path, node
        return
    head, rest = pattern[0], pattern[1:]
    if head == "**":
        yield from walk(node, rest, path)
        children = node.items() if isinstance(node, dict) else enumerate(node) if isinstance(node, list) else []
        for k, v in children:
            yield from walk(v, pattern, path + (k,))
        return
    if isinstance(node, dict):
        items = node.items() if head == "*" else [(head, node[head])] if head in node else []
    elif isinstance(node, list) and head == "*":
        items = enumerate(node)
    else:
        items = []
    for k, v in items:
        yield from walk(v, rest, path + (k,))


def set_at(doc, path, value):
    for k in path[:-1]:
        doc = doc[k]
    doc[path[-1]] = value


def reference_mutations(doc, rng):
    refs = []
    for pattern, collection in REFERENCES:
        for path, value in walk(doc, pattern):
            if isinstance(value, int):
                refs.append((path, collection, value))
    rng.shuffle(refs)
    for path, collection, value in sorted(refs[:PER_MODEL_REFERENCES]):
        size = len(doc.get(collection, []))
        name = "ref-" + "-".join(str(k) for k in path)
        for tag, bad in [("end", size), ("neg", -1), ("2p31", 2**31), ("wrap32", 2**32 + value)]:
            yield name + "-" + tag, lambda d, b, p=path, v=bad: set_at(d, p, v)


def accessor_mutations(doc):
    for i, acc in enumerate(doc.get("accessors", [])):
        if i >= PER_MODEL_OBJECTS and "sparse" not in acc:
            continue
        a = "acc%d-" % i

        def edit(key, value, i=i):
            return lambda d, b: d["accessors"][i].__setitem__(key, value)
        if "bufferView" in acc:
            yield a + "offset+4", edit("byteOffset", acc.get("byteOffset", 0) + 4)
            yield a + "offset-2p64", edit("byteOffset", 2**64 - 4)
            yield a + "count+1", edit("count", acc["count"] + 1)
        yield a + "count0", edit("count", 0)
        yield a + "count-2p32", edit("count", 2**32 - 1)
        yield a + "count-2p62", edit("count", 2**62)
        yield a + "count-float", edit("count", float(acc["count"]))
        yield a + "componentType-bad", edit("componentType", 5124)
        yield a + "type-bad", edit("type", "VEC5")
        if acc["componentType"] == 5126:
            yield a + "normalized-float", edit("normalized", True)
        if "min" in acc:
            yield a + "min-mismatch", edit("min", [m + 1 for m in acc["min"]])
        if "sparse" in acc:
            s = acc["sparse"]
            yield a + "sparse-count-over", lambda d, b, i=i: d["accessors"][i]["sparse"].__setitem__("count", d["accessors"][i]["count"] + 1)
            yield a + "sparse-count0", lambda d, b, i=i: d["accessors"][i]["sparse"].__setitem__("count", 0)
            yield a + "sparse-count-2p62", lambda d, b, i=i: d["accessors"][i]["sparse"].__setitem__("count", 2**62)
            yield a + "sparse-indices-offset-2p64", lambda d, b, i=i: d["accessors"][i]["sparse"]["indices"].__setitem__("byteOffset", 2**64 - 2)
            yield a + "sparse-values-offset+4", lambda d, b, i=i: d["accessors"][i]["sparse"]["values"].__setitem__("byteOffset", s["values"].get("byteOffset", 0) + 4)
            yield a + "sparse-index-oob", lambda d, b, i=i: patch_sparse_index(d, b, i, 0, d["accessors"][i]["count"])
            yield a + "sparse-index-huge", lambda d, b, i=i: patch_sparse_index(d, b, i, 0, 0xFFFF)
            if s["count"] > 1:
                yield a + "sparse-non-increasing", lambda d, b, i=i: patch_sparse_index(d, b, i, 1, 0)


def view_bytes(doc, buffers, view_index):
    view = doc["bufferViews"][view_index]
    return buffers[view["buffer"]], view.get("byteOffset", 0)


def patch_sparse_index(doc, buffers, i, element, value):
    idx = doc["accessors"][i]["sparse"]["indices"]
    fmt, size = gm.COMPONENT[idx["componentType"]]
    data, base = view_bytes(doc, buffers, idx["bufferView"])
    struct.pack_into("<" + fmt, data, base + idx.get("byteOffset", 0) + element * size, value & ((1 << 8 * size) - 1))


def index_mutations(doc):
    for m, mesh in enumerate(doc.get("meshes", [])[:1]):
        for p, prim in enumerate(mesh["primitives"][:1]):
            if "indices" not in prim:
                continue
            acc = doc["accessors"][prim["indices"]]
            vertices = doc["accessors"][prim["attributes"]["POSITION"]]["count"]
            fmt, size = gm.COMPONENT[acc["componentType"]]

            def patch(d, b, acc=acc, fmt=fmt, value=0):
                data, base = view_bytes(d, b, acc["bufferView"])
                struct.pack_into("<" + fmt, data, base + acc.get("byteOffset", 0) + size, value)
            tag = "mesh%d-prim%d-" % (m, p)
            yield tag + "index-oob", lambda d, b, v=vertices: patch(d, b, value=v)
            yield tag + "index-max", lambda d, b, s=size: patch(d, b, value=(1 << 8 * s) - 1)
            yield tag + "indices-float", lambda d, b, a=prim["indices"]: d["accessors"][a].__setitem__("componentType", 5126)
            yield tag + "mode7", lambda d, b, m=m, p=p: d["meshes"][m]["primitives"][p].__setitem__("mode", 7)
            yield tag + "mode-strip", lambda d, b, m=m, p=p: d["meshes"][m]["primitives"][p].__setitem__("mode", 5)
            yield tag + "no-position", lambda d, b, m=m, p=p: d["meshes"][m]["primitives"][p]["attributes"].pop("POSITION")
            yield tag + "attributes-empty", lambda d, b, m=m, p=p: d["meshes"][m]["primitives"][p].__setitem__("attributes", {})


def view_mutations(doc):
    for j, view in enumerate(doc.get("bufferViews", [])[:PER_MODEL_OBJECTS]):
        tag = "view%d-" % j

        def edit(key, value, j=j):
            return lambda d, b: d["bufferViews"][j].__setitem__(key, value)
        yield tag + "length+4", edit("byteLength", view["byteLength"] + 4)
        yield tag + "length0", edit("byteLength", 0)
        yield tag + "offset-past-buffer", edit("byteOffset", doc["buffers"][view["buffer"]]["byteLength"])
        yield tag + "offset-2p64", edit("byteOffset", 2**64 - 8)
        yield tag + "stride3", edit("byteStride", 3)
        yield tag + "stride256", edit("byteStride", 256)


def buffer_mutations(doc):
    for k in range(len(doc.get("buffers", []))):
        yield "buffer%d-length+4" % k, lambda d, b, k=k: d["buffers"][k].__setitem__("byteLength", len(b[k]) + 4)
        yield "buffer%d-length-2p53" % k, lambda d, b, k=k: d["buffers"][k].__setitem__("byteLength", 2**53)
        yield "buffer%d-bad-base64" % k, lambda d, b, k=k: d["buffers"][k].__setitem__("uri", "data:application/octet-stream;base64,@@@@")
        yield "buffer%d-missing-file" % k, lambda d, b, k=k: d["buffers"][k].__setitem__("uri", "missing.bin")


def node_mutations(doc):
    if not doc.get("nodes"):
        return
    def edit(key, value):
        return lambda d, b: d["nodes"][0].__setitem__(key, value)
    yield "node0-matrix-shear", edit("matrix", [1, 0, 0, 0, 1, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1])
    yield "node0-matrix-and-trs", lambda d, b: d["nodes"][0].update(matrix=[1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1], translation=[1, 0, 0])
    yield "node0-rotation-non-unit", edit("rotation", [0, 0, 0, 2])
    yield "node0-scale-1e39", edit("scale", [1e39, 1, 1])
    yield "node0-translation-1e39", edit("translation", [1e39, 0, 0])
    yield "node0-matrix-short", edit("matrix", [1, 0, 0])
    yield "node0-self-child", edit("children", [0])
    if len(doc["nodes"]) > 1:
        yield "node-cycle", lambda d, b: (d["nodes"][0].__setitem__("children", [1]), d["nodes"][1].__setitem__("children", [0]))


def camera_mutations(doc):
    for c, cam in enumerate(doc.get("cameras", [])[:PER_MODEL_OBJECTS]):
        kind = cam["type"]
        tag = "camera%d-" % c

        def edit(key, value, c=c, kind=kind):
            return lambda d, b: d["cameras"][c][kind].__setitem__(key, value)
        if kind == "perspective":
            yield tag + "yfov0", edit("yfov", 0)
            yield tag + "yfov-pi", edit("yfov", 3.2)
            yield tag + "znear0", edit("znear", 0)
            yield tag + "zfar-below-znear", edit("zfar", cam[kind]["znear"] / 2)
            yield tag + "aspect-neg", edit("aspectRatio", -1)
            yield tag + "zfar-1e308", edit("zfar", 1e308)
        else:
            yield tag + "xmag0", edit("xmag", 0)
            yield tag + "zfar-below-znear", edit("zfar", -1)
        yield tag + "type-bad", lambda d, b, c=c: d["cameras"][c].__setitem__("type", "fisheye")


def material_mutations(doc):
    for i in range(min(len(doc.get("materials", [])), 1)):
        tag = "material%d-" % i
        pbr = lambda d, i=i: d["materials"][i].setdefault("pbrMetallicRoughness", {})
        yield tag + "basecolor-2", lambda d, b: pbr(d).__setitem__("baseColorFactor", [2, 0, 0, 1])
        yield tag + "metallic-neg", lambda d, b: pbr(d).__setitem__("metallicFactor", -1)
        yield tag + "alpha-mode-bad", lambda d, b, i=i: d["materials"][i].__setitem__("alphaMode", "GLOW")
        if "baseColorTexture" in doc["materials"][i].get("pbrMetallicRoughness", {}):
            yield tag + "texcoord5", lambda d, b: pbr(d)["baseColorTexture"].__setitem__("texCoord", 5)
            yield tag + "transform-scale-1e300", lambda d, b: pbr(d)["baseColorTexture"].setdefault("extensions", {}).__setitem__(
                "KHR_texture_transform", {"scale": [1e300, 1e300]})


def document_mutations(doc):
    yield "asset-missing", lambda d, b: d.pop("asset")
    yield "asset-version-3", lambda d, b: d["asset"].__setitem__("version", "3.0")
    yield "unknown-property", lambda d, b: d.__setitem__("shadelgraphUnknown", 1)
    yield "extension-used-unknown", lambda d, b: d.setdefault("extensionsUsed", []).append("EXT_unknown_thing")
    yield "extension-required-unknown", lambda d, b: (d.setdefault("extensionsUsed", []).append("EXT_unknown_thing"),
                                                       d.setdefault("extensionsRequired", []).append("EXT_unknown_thing"))
    yield "extras-nested-200", lambda d, b: d["asset"].__setitem__("extras", nested(200))
    yield "name-not-string", lambda d, b: d["asset"].__setitem__("generator", 7)
    yield "scene-not-int", lambda d, b: d.__setitem__("scene", "0")


def nested(depth):
    value = 0
    for _ in range(depth):
        value = [value]
    return value


def json_text_mutations(text):
    """Mutations of the JSON text itself: (name, bytes)."""
    yield "json-truncated", text[: len(text) // 2]
    yield "json-trailing-garbage", text + b"}]"
    yield "json-empty", b""
    yield "json-not-object", b"[]"
    yield "json-nested-20000", text[:-1] + b',"extras":' + b"[" * 20000 + b"]" * 20000 + b"}"
    yield "json-number-1e999", text.replace(b'"asset":{', b'"asset":{"extras":1e999,', 1)


def glb_mutations(data):
    """Container mutations of a valid GLB: (name, bytes)."""
    json_len = struct.unpack_from("<I", data, 12)[0]
    bin_at = 20 + json_len
    has_bin = len(data) > bin_at
    def put(offset, fmt, value):
        out = bytearray(data)
        struct.pack_into(fmt, out, offset, value)
        return bytes(out)
    yield "glb-version1", put(4, "<I", 1)
    yield "glb-version3", put(4, "<I", 3)
    yield "glb-magic", b"gltf" + data[4:]
    yield "glb-length+4", put(8, "<I", len(data) + 4)
    yield "glb-length-4", put(8, "<I", len(data) - 4)
    yield "glb-length0", put(8, "<I", 0)
    yield "glb-json-length+4", put(12, "<I", json_len + 4)
    yield "glb-json-length-2p32", put(12, "<I", 0xFFFFFFFC)
    yield "glb-json-length0", put(12, "<I", 0)
    yield "glb-json-type", put(16, "<I", 0x58585858)
    yield "glb-truncated-header", data[:11]
    yield "glb-truncated-chunk-header", data[:19]
    yield "glb-truncated-json", data[: bin_at - 3]
    yield "glb-unknown-chunk", put(8, "<I", len(data) + 12) + struct.pack("<II", 4, 0x12345678) + b"abcd"
    if has_bin:
        bin_len = struct.unpack_from("<I", data, bin_at)[0]
        yield "glb-bin-length+8", put(bin_at, "<I", bin_len + 8)
        yield "glb-bin-length-4", put(bin_at, "<I", bin_len - 4)
        yield "glb-bin-length-2p32", put(bin_at, "<I", 0xFFFFFFF0)
        yield "glb-bin-truncated", put(8, "<I", len(data) - 4)[:-4]
        yield "glb-bin-missing", put(8, "<I", bin_at)[:bin_at]
        yield "glb-bin-twice", put(8, "<I", len(data) + len(data) - bin_at) + data[bin_at:]


def write(name, data):
    with open(os.path.join(OUT, name), "wb") as f:
        f.write(data)


def main():
    shutil.rmtree(OUT, ignore_errors=True)
    os.makedirs(OUT)
    rng = random.Random(13)
    count = 0
    for model in MODELS:
        doc, buffers = gm.minimized(os.path.join(ASSETS, model, "glTF", model + ".gltf"))
        write(model + "-valid.gltf", gm.to_gltf(doc, buffers))
        write(model + "-valid.glb", gm.to_glb(doc, buffers))
        count += 2
        families = [reference_mutations(doc, rng), accessor_mutations(doc), index_mutations(doc), view_mutations(doc),
                    buffer_mutations(doc), node_mutations(doc), camera_mutations(doc), material_mutations(doc)]
        if model == "Box":  # these do not depend on the model
            families.append(document_mutations(doc))
        for i, family in enumerate(families):
            for name, mutate in family:
                d, b = copy.deepcopy(doc), [bytearray(x) for x in buffers]
                mutate(d, b)
                b = [bytes(x) for x in b]
                # Alternate containers so both parsers see every kind of change.
                glb = (count % 3 == 0) and not name.startswith("buffer")
                if glb:
                    write("%s-%s.glb" % (model, name), gm.to_glb(d, b))
                else:
                    write("%s-%s.gltf" % (model, name), gm.to_gltf(d, b))
                count += 1
        if model in ("Box", "Triangle", "BoxTextured"):
            for name, data in json_text_mutations(gm.to_gltf(doc, buffers)):
                write("%s-%s.gltf" % (model, name), data)
                count += 1
            for name, data in glb_mutations(gm.to_glb(doc, buffers)):
                write("%s-%s.glb" % (model, name), data)
                count += 1
    print("wrote %d files to %s" % (count, os.path.relpath(OUT, ROOT)))


if __name__ == "__main__":
    main()
