#!/usr/bin/env python3
"""Plots of `shadelgraph bench` results: accuracy against time (each
configuration a point, the Pareto front drawn) and per-pass stacked GPU time
bars, one pair per scene and size. Usage: plot_bench.py RESULTS_DIR"""
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


def main():
    out = Path(sys.argv[1] if len(sys.argv) > 1 else "out/bench")
    results = json.loads((out / "results.json").read_text())
    for run in results["runs"]:
        plot_run(run, out)
    print(f"wrote plots to {out}")


if __name__ == "__main__":
    main()
