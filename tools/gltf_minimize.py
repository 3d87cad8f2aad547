"""Small, self-contained versions of the Khronos sample models, for the fuzz
seed corpus and the hostile corpus: buffers embedded (data: URIs or one GLB
BIN chunk), images replaced by a 2x2 PNG, and in models whose buffers exceed
SMALL_BYTES every accessor cut to MAX_COUNT elements (indices wrapped to stay
in range, min/max recomputed). Deterministic: same models, same bytes."""
import base64
import copy
import json
import os
import struct
import zlib

SMALL_BYTES = 16 * 1024
MAX_COUNT = 24

COMPONENT = {5120: ("b", 1), 5121: ("B", 1), 5122: ("h", 2), 5123: ("H", 2), 5125: ("I", 4), 5126: ("f", 4)}
TYPE = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4, "MAT2": 4, "MAT3": 9, "MAT4": 16}


def tiny_png():
    """A 2x2 RGBA PNG (stb_image decodes it)."""
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)
    rows = b"".join(b"\0" + bytes([255, 0, 0, 255, 0, 255, 0, 255]) for _ in range(2))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", 2, 2, 8, 6, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b""))


PNG_URI = "data:image/png;base64," + base64.b64encode(tiny_png()).decode()


def element_size(acc):
    fmt, size = COMPONENT[acc["componentType"]]
    return size * TYPE[acc["type"]], fmt, TYPE[acc["type"]]


def read_buffers(doc, folder):
    out = []
    for b in doc.get("buffers", []):
        uri = b.get("uri", "")
        if uri.startswith("data:"):
            out.append(base64.b64decode(uri.split(",", 1)[1]))
        else:
            with open(os.path.join(folder, uri), "rb") as f:
                out.append(f.read())
    return out


def cut(doc, buffers):
    """Every accessor with a bufferView gets its own view of at most MAX_COUNT elements in one new buffer."""
    views = doc.get("bufferViews", [])
    index_limit = {}
    for mesh in doc.get("meshes", []):
        for p in mesh.get("primitives", []):
            if "indices" in p and "POSITION" in p.get("attributes", {}):
                count = min(doc["accessors"][p["attributes"]["POSITION"]]["count"], MAX_COUNT)
                index_limit[p["indices"]] = min(index_limit.get(p["indices"], count), count)
    data = bytearray()
    new_views = []
    for i, acc in enumerate(doc.get("accessors", [])):
        acc.pop("sparse", None)
        if "bufferView" not in acc:
            continue
        view = views[acc["bufferView"]]
        size, fmt, n = element_size(acc)
        stride = view.get("byteStride", size)
        count = min(acc["count"], MAX_COUNT)
        src = buffers[view["buffer"]]
        start = view.get("byteOffset", 0) + acc.get("byteOffset", 0)
        values = []
        for e in range(count):
            values.append(list(struct.unpack_from("<%d%s" % (n, fmt), src, start + e * stride)))
        if i in index_limit:
            values = [[v[0] % index_limit[i]] for v in values]
        packed = b"".join(struct.pack("<%d%s" % (n, fmt), *v) for v in values)
        while len(data) % 4:
            data.append(0)
        new_view = {"buffer": 0, "byteOffset": len(data), "byteLength": len(packed)}
        if "target" in view:
            new_view["target"] = view["target"]
        data += packed
        acc["bufferView"] = len(new_views)
        acc["byteOffset"] = 0
        acc["count"] = count
        if "min" in acc or "max" in acc:
            acc["min"] = [min(v[c] for v in values) for c in range(n)]
            acc["max"] = [max(v[c] for v in values) for c in range(n)]
        new_views.append(new_view)
    doc["bufferViews"] = new_views
    doc["buffers"] = [{"byteLength": len(data)}]
    return [bytes(data)]


def minimized(path):
    """(document, buffers) of the .gltf at path, small and without external files."""
    with open(path) as f:
        doc = json.load(f)
    buffers = read_buffers(doc, os.path.dirname(path))
    doc = copy.deepcopy(doc)
    if sum(len(b) for b in buffers) > SMALL_BYTES:
        buffers = cut(doc, buffers)
    for image in doc.get("images", []):
        image.pop("bufferView", None)
        image.pop("mimeType", None)
        image["uri"] = PNG_URI
    return doc, buffers


def to_gltf(doc, buffers):
    doc = copy.deepcopy(doc)
    for b, data in zip(doc.get("buffers", []), buffers):
        b["uri"] = "data:application/octet-stream;base64," + base64.b64encode(data).decode()
        b["byteLength"] = len(data)
    return json.dumps(doc, separators=(",", ":")).encode()


def glb(json_bytes, bin_bytes=None, version=2):
    """A GLB container: header, JSON chunk (space-padded), optional BIN chunk (zero-padded)."""
    json_bytes += b" " * (-len(json_bytes) % 4)
    out = struct.pack("<II", len(json_bytes), 0x4E4F534A) + json_bytes
    if bin_bytes is not None:
        bin_bytes += b"\0" * (-len(bin_bytes) % 4)
        out += struct.pack("<II", len(bin_bytes), 0x004E4942) + bin_bytes
    return struct.pack("<4sII", b"glTF", version, 12 + len(out)) + out


def to_glb(doc, buffers):
    """All buffers merged into the BIN chunk."""
    doc = copy.deepcopy(doc)
    data = bytearray()
    bases = []
    for b in buffers:
        while len(data) % 4:
            data.append(0)
        bases.append(len(data))
        data += b
    for view in doc.get("bufferViews", []):
        if isinstance(view.get("buffer"), int) and 0 <= view["buffer"] < len(bases):  # else left as hostile as it is
            view["byteOffset"] = view.get("byteOffset", 0) + bases[view["buffer"]]
            view["buffer"] = 0
    if buffers:
        doc["buffers"] = [{"byteLength": len(data)}]
        return glb(json.dumps(doc, separators=(",", ":")).encode(), bytes(data))
    return glb(json.dumps(doc, separators=(",", ":")).encode())


def sample_models(assets):
    """(name, path) of every sample model's .gltf, sorted."""
    out = []
    for name in sorted(os.listdir(assets)):
        path = os.path.join(assets, name, "glTF", name + ".gltf")
        if os.path.isfile(path):
            out.append((name, path))
    return out
