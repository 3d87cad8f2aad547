#!/usr/bin/env python3
"""Writes the fuzz seed corpus in tests/fuzz/corpus (committed; rerun after
changing this script): every sample model of ../shared/assets/gltf minimized
(tools/gltf_minimize.py) as .gltf and .glb, scene files placing them, and
command lines. Deterministic."""
import json
import os
import shutil
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import gltf_minimize as gm  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ASSETS = os.path.join(ROOT, "..", "shared", "assets", "gltf")
CORPUS = os.path.join(ROOT, "tests", "fuzz", "corpus")


def write(path, data):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "wb") as f:
        f.write(data if isinstance(data, bytes) else data.encode())


def gltf_seeds():
    for name, path in gm.sample_models(ASSETS):
        doc, buffers = gm.minimized(path)
        write(os.path.join(CORPUS, "gltf", name + ".gltf"), gm.to_gltf(doc, buffers))
        write(os.path.join(CORPUS, "gltf", name + ".glb"), gm.to_glb(doc, buffers))


def scene_seeds():
    """tests/scenes/*.json with the models renamed to seeds, and one file per feature."""
    seeds = {}
    for scene in sorted(os.listdir(os.path.join(ROOT, "tests", "scenes"))):
        with open(os.path.join(ROOT, "tests", "scenes", scene)) as f:
            doc = json.load(f)
        for o in doc.get("objects", []):
            o["gltf"] = os.path.splitext(os.path.basename(o["gltf"]))[0] + ".gltf"
        seeds["tests-" + scene] = doc
    seeds["empty.json"] = {"objects": []}
    seeds["two-files.json"] = {"objects": [
        {"gltf": "Box.glb", "name": "a", "translation": [1, 2, 3], "rotation": [0, 0, 0, 1], "scale": 2,
         "shading": "decoupled"},
        {"gltf": "Box.glb", "rotationDegrees": [0, 90, 0], "scale": [1, 2, 1], "shading": "forward"},
        {"gltf": "Triangle.gltf", "shading": "auto"}]}
    seeds["lights.json"] = {"objects": [{"gltf": "Cameras.gltf"}], "lights": [
        {"type": "directional", "direction": [-1, -1, -1], "color": [1, 1, 1], "intensity": 3},
        {"type": "point", "position": [0, 3, 0], "intensity": 20, "range": 10},
        {"type": "spot", "position": [0, 3, 3], "direction": [0, -1, -1], "innerConeAngle": 0.2,
         "outerConeAngle": 0.5, "name": "key"}]}
    seeds["paths.json"] = {"objects": [{"gltf": "SimpleSparseAccessor.gltf"}], "cameraPaths": [
        {"name": "orbit", "type": "orbit", "center": [0, 1, 0], "radius": 4, "height": 1, "seconds": 10},
        {"name": "fly", "type": "keys", "keys": [{"t": 0, "position": [0, 1, 5], "target": [0, 1, 0]},
                                                 {"t": 4, "position": [3, 2, 3], "target": [0, 1, 0]}]}]}
    seeds["bad-unknown-key.json"] = {"objects": [{"gltf": "Box.gltf", "shadng": "forward"}]}
    for name, doc in seeds.items():
        write(os.path.join(CORPUS, "scene", name), json.dumps(doc, indent=1) + "\n")


def cli_seeds():
    """One argument per line (tests/fuzz/fuzz_cli.cpp splits on newlines)."""
    lines = {
        "render.txt": ["render", "Box.gltf", "-o", "out.png", "--size", "64x64", "--mode", "decoupled",
                       "--filter", "1", "--view", "level", "--bias", "0.5", "--storage", "1.5", "--frames", "3",
                       "--stats", "s.json", "--trace", "t.json", "--no-aliasing", "--material", "bumps"],
        "render-path.txt": ["render", "scene.json", "--frame", "10", "--path", "1", "--camera", "0"],
        "graph.txt": ["graph", "--size", "1280x720", "--dot", "--plugin", "a.so", "--plugin-dir", "plugins"],
        "graph-json.txt": ["graph", "scene.glb", "--json", "--mode", "forward"],
        "inspect.txt": ["inspect", "Box.gltf"],
        "inspect-glb.txt": ["inspect", "SimpleSparseAccessor.glb"],
        "inspect-help.txt": ["inspect", "--help"],
        "bench.txt": ["bench", "a.gltf", "b.json", "--out", "res", "--sizes", "640x360", "1280x720",
                      "--repetitions", "5", "--flicker-frames", "8", "--reference-scale", "4", "--shimmer"],
        "bench-graph.txt": ["bench", "graph", "--passes", "10,100", "--graphs", "3", "--repetitions", "2"],
        "help.txt": ["--help"],
        "version.txt": ["--version"],
        "render-help.txt": ["render", "--help"],
    }
    for name, args in lines.items():
        write(os.path.join(CORPUS, "cli", name), "\n".join(args) + "\n")


if __name__ == "__main__":
    shutil.rmtree(CORPUS, ignore_errors=True)
    gltf_seeds()
    scene_seeds()
    cli_seeds()
