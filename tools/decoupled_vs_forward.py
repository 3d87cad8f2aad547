#!/usr/bin/python3
"""Decoupled against forward, model by model: renders each glTF sample model
with `shadelgraph render --mode decoupled` and `--mode forward` at each size
(same camera, same frame count) and prints, per model and size, the PSNR of
the two frames over RGB (as framework/image's compareRgba8), the shadels per
covered pixel and the objects left forward. Models with no decoupled object
are listed as such. Images and a difference image (|d| × 8) go to OUT_DIR.

Usage: decoupled_vs_forward.py SHADELGRAPH MODELS_DIR OUT_DIR
       [--sizes 640x360,1280x720] [--only A,B] [-- extra render arguments]
Needs numpy and PIL (Debian's python3-numpy, python3-pil)."""
import argparse
import json
import math
import subprocess
import sys
from pathlib import Path

import numpy as np
from PIL import Image


def render(shadelgraph, model, mode, size, png, stats, extra):
    cmd = [shadelgraph, "render", str(model), "--mode", mode, "--size", size, "-o", str(png),
           "--stats", str(stats)] + extra
    done = subprocess.run(cmd, capture_output=True, text=True)
    if done.returncode != 0:
        raise RuntimeError(f"{model.name} {mode} {size}: {done.stderr.strip() or done.stdout.strip()}")
    return json.loads(stats.read_text())


def rgb(png):
    return np.asarray(Image.open(png).convert("RGB"), dtype=np.float64)


def psnr(a, b):
    mse = float(np.mean((a - b) ** 2))
    return math.inf if mse == 0 else 10 * math.log10(255.0 * 255.0 / mse)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("shadelgraph")
    parser.add_argument("models", type=Path)
    parser.add_argument("out", type=Path)
    parser.add_argument("--sizes", default="640x360,1280x720")
    parser.add_argument("--only", default="")
    parser.add_argument("--reference", type=int, default=0,
                        help="also a forward render at N times the size, box-filtered (N² samples a pixel, as the "
                             "bench's reference): PSNR of decoupled and of forward against it")
    argv = sys.argv[1:]
    split = argv.index("--") if "--" in argv else len(argv)
    args = parser.parse_args(argv[:split])
    args.extra = argv[split + 1:]
    args.out.mkdir(parents=True, exist_ok=True)
    only = set(filter(None, args.only.split(",")))
    rows = []
    for model_dir in sorted(p for p in args.models.iterdir() if p.is_dir()):
        if only and model_dir.name not in only:
            continue
        files = sorted((model_dir / "glTF").glob("*.gltf"))
        if not files:
            continue
        for size in args.sizes.split(","):
            stem = args.out / f"{model_dir.name}-{size}"
            try:
                dec = render(args.shadelgraph, files[0], "decoupled", size, Path(f"{stem}-decoupled.png"),
                             Path(f"{stem}-decoupled.json"), args.extra)
                if dec["objects_decoupled"] == 0:
                    rows.append((model_dir.name, size, None, None, 0, dec["objects_forward"]))
                    continue
                render(args.shadelgraph, files[0], "forward", size, Path(f"{stem}-forward.png"),
                       Path(f"{stem}-forward.json"), args.extra)
            except RuntimeError as error:
                print(f"error: {error}", file=sys.stderr)
                continue
            a, b = rgb(f"{stem}-decoupled.png"), rgb(f"{stem}-forward.png")
            ref_db = ""
            if args.reference > 1:
                n = args.reference
                w, h = (int(v) for v in size.split("x"))
                render(args.shadelgraph, files[0], "forward", f"{w * n}x{h * n}", Path(f"{stem}-big.png"),
                       Path(f"{stem}-big.json"), args.extra)
                big = rgb(f"{stem}-big.png")
                ref = np.round(big.reshape(h, n, w, n, 3).mean(axis=(1, 3)))
                Path(f"{stem}-big.png").unlink()
                Image.fromarray(ref.astype(np.uint8)).save(f"{stem}-reference.png")
                ref_db = f" | vs {n * n}-spp reference: decoupled {psnr(a, ref):.1f} forward {psnr(b, ref):.1f}"
            diff = np.clip(np.abs(a - b).max(axis=2) * 8, 0, 255).astype(np.uint8)
            Image.fromarray(diff).save(f"{stem}-diff.png")
            rows.append((model_dir.name, size, psnr(a, b), dec["shadels_per_pixel"], dec["objects_decoupled"],
                         dec["objects_forward"]))
            print(f"{model_dir.name:30} {size:10} {rows[-1][2]:6.1f} dB {rows[-1][3]:5.2f} shadels/px "
                  f"{rows[-1][4]} decoupled {rows[-1][5]} forward{ref_db}", flush=True)
    print("\n| model | size | dB | shadels/px | objects decoupled / forward |\n|---|---|---|---|---|")
    for name, size, db, spp, d, f in rows:
        if db is None:
            print(f"| {name} | {size} | (nothing decoupled) | | 0 / {f} |")
        else:
            print(f"| {name} | {size} | {db:.1f} | {spp:.2f} | {d} / {f} |")


if __name__ == "__main__":
    main()
