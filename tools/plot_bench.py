#!/usr/bin/env python3
"""Plots of `shadelgraph bench` results in RESULTS_DIR, for each file present:
- results.json: accuracy against time (each configuration a point, the Pareto
  front drawn) and per-pass stacked GPU time bars, one pair per scene and size;
- materials.json (bench --materials): accuracy against time, each material's
  forward and decoupled runs joined;
- graph.json (bench graph): declare + compile time against graph size, log-log,
  with the linear growth from the smallest size for comparison.
Usage: plot_bench.py RESULTS_DIR"""
import json
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def pareto(points):
    """Points not beaten in both time and error, sorted by time."""
    front, best = [], float("inf")
    for t, e, name in sorted(points):
        if e < best:
            front.append((t, e, name))
            best = e
    return front


def plot_run(run, out):
    tag = f"{run['scene']}-{run['width']}x{run['height']}"
    configs = run["configs"]
    fig, ax = plt.subplots(figsize=(7, 5))
    points = [(c["frame_ms_median"], c["flip_mean"], c["config"]) for c in configs]
    for t, e, name in points:
        ax.scatter(t, e, color="tab:red" if name == "forward" else "tab:blue", zorder=3)
        ax.annotate(name, (t, e), textcoords="offset points", xytext=(4, 4), fontsize=7)
    front = pareto(points)
    ax.plot([p[0] for p in front], [p[1] for p in front], "--", color="gray", zorder=2, label="Pareto front")
    ax.set_xlabel("median frame GPU time (ms)")
    ax.set_ylabel("mean FLIP vs 16-spp reference (lower is better)")
    ax.set_title(f"Accuracy against time: {tag}")
    ax.grid(alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(out / f"accuracy-vs-time-{tag}.png", dpi=110)
    plt.close(fig)

    passes = sorted({p for c in configs for p in c["pass_ms_median"]})
    fig, ax = plt.subplots(figsize=(9, 5))
    bottoms = [0.0] * len(configs)
    colors = plt.get_cmap("tab20").colors
    for i, p in enumerate(passes):
        values = [c["pass_ms_median"].get(p, 0.0) for c in configs]
        ax.bar(range(len(configs)), values, bottom=bottoms, label=p, color=colors[i % len(colors)])
        bottoms = [b + v for b, v in zip(bottoms, values)]
    ax.set_xticks(range(len(configs)))
    ax.set_xticklabels([c["config"] for c in configs], rotation=35, ha="right", fontsize=8)
    ax.set_ylabel("median GPU time per pass (ms)")
    ax.set_title(f"Per-pass time: {tag}")
    ax.legend(fontsize=7, ncol=2)
    fig.tight_layout()
    fig.savefig(out / f"pass-times-{tag}.png", dpi=110)
    plt.close(fig)


def plot_materials(run, out):
    tag = f"{run['scene']}-{run['width']}x{run['height']}"
    fig, ax = plt.subplots(figsize=(7, 5))
    materials = sorted({c["material"] for c in run["configs"]})
    colors = plt.get_cmap("tab10").colors
    for i, material in enumerate(materials):
        configs = [c for c in run["configs"] if c["material"] == material]
        points = [(c["gpu_ms_median"], c["flip_mean"], c["path"]) for c in configs]
        ax.plot([p[0] for p in points], [p[1] for p in points], "-", color=colors[i % 10], alpha=0.5, label=material)
        for t, e, path in points:
            ax.scatter(t, e, color=colors[i % 10], marker="o" if path == "decoupled" else "s", zorder=3)
    ax.set_xlabel("median frame GPU time (ms)")
    ax.set_ylabel("mean FLIP vs the same material's reference")
    ax.set_title(f"Material layers, forward (square) and decoupled (circle): {tag}", fontsize=10)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out / f"materials-{tag}.png", dpi=110)
    plt.close(fig)


def plot_graph(results, out):
    sizes = results["sizes"]
    passes = [s["passes"] for s in sizes]
    fig, ax = plt.subplots(figsize=(6, 4.5))
    for mode, color in (("fresh", "tab:red"), ("reused", "tab:blue")):
        medians = [s[mode]["median_us"] for s in sizes]
        ax.errorbar(passes, medians, yerr=[[m - s[mode]["p10_us"] for m, s in zip(medians, sizes)],
                                           [s[mode]["p90_us"] - m for m, s in zip(medians, sizes)]],
                    marker="o", color=color, capsize=3, label=f"{mode} (median, p10-p90)")
        ax.plot(passes, [medians[0] * p / passes[0] for p in passes], ":", color=color, alpha=0.6,
                label=f"{mode}: linear from {passes[0]} passes")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("passes")
    ax.set_ylabel("declare + compile (µs)")
    ax.set_title("Render graph compile cost")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out / "graph-compile.png", dpi=110)
    plt.close(fig)


def main():
    out = Path(sys.argv[1] if len(sys.argv) > 1 else "out/bench")
    found = False
    if (out / "results.json").exists():
        for run in json.loads((out / "results.json").read_text())["runs"]:
            plot_run(run, out)
        found = True
    if (out / "materials.json").exists():
        for run in json.loads((out / "materials.json").read_text())["runs"]:
            plot_materials(run, out)
        found = True
    if (out / "graph.json").exists():
        plot_graph(json.loads((out / "graph.json").read_text()), out)
        found = True
    if not found:
        sys.exit(f"plot_bench.py: no results.json, materials.json or graph.json in {out}")
    print(f"wrote plots to {out}")


if __name__ == "__main__":
    main()
