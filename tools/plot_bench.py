#!/usr/bin/env python3
"""Plots of `shadelgraph bench` results in RESULTS_DIR, for each file present:
- results.json: accuracy against time (each configuration a point, the Pareto
  front drawn) and per-pass stacked GPU time bars, one pair per scene and size;
- materials.json (bench --materials): accuracy against time, each material's
  forward and decoupled runs joined;
- shade-rate.json (bench --shade-rates): per scene and size, the raster
  frame's median and mean against forward by configuration (the issue's
  targets 0.8 and 0.6 marked), ꟻLIP and flicker against frame time, and the
  frame split into raster passes, shade-space bookkeeping, shading and gaps;
- graph.json (bench graph): declare + compile time against graph size, log-log,
  with the linear growth from the smallest size for comparison;
- effects.json (bench --effects): per size, light culling against brute force
  by light count (log-log, both paths), frame time by shadowed lights per
  light type, and environment light and bloom on against off.
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


def plot_shade_rate(run, out):
    tag = f"{run['scene']}-{run['width']}x{run['height']}"
    configs = run["configs"]
    names = [c["config"].replace("decoupled ", "") for c in configs]
    fig, axes = plt.subplots(1, 4, figsize=(22, 5))

    ax = axes[0]
    x = range(len(configs))
    ax.bar([i - 0.2 for i in x], [c["ratio_to_forward"] for c in configs], 0.4, label="median frame")
    ax.bar([i + 0.2 for i in x], [c["ratio_mean_to_forward"] for c in configs], 0.4, label="mean frame")
    tails = [(i, c["ratio_mean_with_tail_to_forward"]) for i, c in enumerate(configs) if c.get("tail_ms_median")]
    if tails:
        ax.scatter([t[0] + 0.2 for t in tails], [t[1] for t in tails], marker="_", s=300, color="black", zorder=3,
                   label="mean frame + its tail")
    for target, style in ((0.8, "--"), (0.6, ":")):
        ax.axhline(target, linestyle=style, color="gray", label=f"target {target}× (rate {2 if target == 0.8 else 4})")
    ax.axhline(1.0, color="tab:red", linewidth=0.8)
    ax.set_xticks(list(x))
    ax.set_xticklabels(names, rotation=35, ha="right", fontsize=8)
    ax.set_ylabel("raster frame ÷ forward (GPU time)")
    ax.set_title("Cost against forward", fontsize=10)
    ax.legend(fontsize=7)

    ax = axes[1]
    for c, name in zip(configs, names):
        color = "tab:red" if not c["decoupled"] else ("tab:green" if c.get("in_flight") else "tab:blue")
        ax.scatter(c["frame_ms_mean"], c["flip_mean"], color=color, zorder=3)
        ax.annotate(name, (c["frame_ms_mean"], c["flip_mean"]), textcoords="offset points", xytext=(4, 4), fontsize=7)
    ax.set_xlabel("mean raster frame GPU time (ms)")
    ax.set_ylabel("mean FLIP vs 16-spp reference of the same frame")
    ax.set_title("Error against time", fontsize=10)
    ax.grid(alpha=0.3)
    twin = ax.twinx()
    twin.scatter([c["frame_ms_mean"] for c in configs], [c["flicker_excess"] for c in configs], marker="x",
                 color="gray", label="flicker excess (right)")
    twin.set_ylabel("flicker excess (T(test) − T(reference))")
    twin.legend(fontsize=7, loc="lower right")

    ax = axes[2]
    groups = (("raster", "raster passes"), ("shade_space", "shade space"), ("shading", "shading"), ("gaps", "gaps"))
    bottoms = [0.0] * len(configs)
    for key, label in groups:
        values = [(c["pass_groups_ms_median"] or {}).get(key, 0.0) for c in configs]
        ax.bar(list(x), values, bottom=bottoms, label=label)
        bottoms = [b + v for b, v in zip(bottoms, values)]
    ax.axhline(configs[0]["frame_ms_median"], color="tab:red", linewidth=0.8, label="forward frame")
    ax.set_xticks(list(x))
    ax.set_xticklabels(names, rotation=35, ha="right", fontsize=8)
    ax.set_ylabel("median ms per raster frame")
    ax.set_title("Where the raster frame goes", fontsize=10)
    ax.legend(fontsize=7)

    # Staleness: each frame's FLIP minus rate 1's at the same pose (shading lagging the camera).
    ax = axes[3]
    rate1 = next((c for c in configs if c["decoupled"] and c["shade_rate"] == 1 and c.get("budget_ms") is None
                  and not c.get("in_flight") and c.get("keep_view_independent_layers", True)), None)
    if rate1:
        for c, name in zip(configs, names):
            if not c["decoupled"] or c is rate1:
                continue
            delta = [a - b for a, b in zip(c["flip_samples"], rate1["flip_samples"])]
            ax.plot(range(len(delta)), delta, "--" if c.get("in_flight") else "-", label=name)
        ax.axhline(0.0, color="gray", linewidth=0.8)
        ax.legend(fontsize=7)
    ax.set_xlabel("path frame")
    ax.set_ylabel("FLIP − rate 1's FLIP, same frame")
    ax.set_title("What staleness adds, frame by frame", fontsize=10)
    ax.grid(alpha=0.3)

    fig.suptitle(f"Shade rates along a moving camera: {tag}")
    fig.tight_layout()
    fig.savefig(out / f"shade-rate-{tag}.png", dpi=100)
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


def plot_effects(run, out):
    tag = f"{run['width']}x{run['height']}"
    panels = [k for k in ("lights", "shadows", "ibl", "bloom") if k in run]
    fig, axes = plt.subplots(1, len(panels), figsize=(5 * len(panels), 4.2), squeeze=False)
    colors = {"forward": "tab:red", "decoupled": "tab:blue"}
    for ax, panel in zip(axes[0], panels):
        if panel == "lights":
            for path, color in colors.items():
                rows = [r for r in run["lights"]["rows"] if r["path"] == path]
                counts = [r["lights"] for r in rows]
                ax.plot(counts, [r["culled_ms_median"] for r in rows], "o-", color=color, label=f"{path} culled")
                ax.plot(counts, [r["brute_force_ms_median"] for r in rows], "s--", color=color,
                        label=f"{path} brute force")
            ax.set_xscale("log")
            ax.set_yscale("log")
            ax.set_xlabel("point lights (each floor point in reach of ~%g)" % run["lights"]["lights_in_reach"])
            ax.set_ylabel("GPU frame ms (median)")
            ax.set_title("Light culling")
        elif panel == "shadows":
            for g in run["shadows"]:
                style = {"directional": "o", "spot": "s", "point": "^"}[g["light_type"]]
                rows = g["rows"]
                ax.plot([r["shadowed"] for r in rows], [r["ratio_to_unshadowed"] for r in rows], style + "-",
                        color=colors[g["path"]], label=f"{g['light_type']} {g['path']}")
            ax.set_xlabel("shadowed lights (of the same lights)")
            ax.set_ylabel("frame time ÷ unshadowed")
            ax.set_title("Shadows")
        else:
            key_on, key_off, label = (("environment_ms_median", "analytic_sky_ms_median", "environment / sky")
                                      if panel == "ibl" else ("bloom_ms_median", "no_bloom_ms_median", "bloom on / off"))
            rows = run[panel]["rows"]
            x = range(len(rows))
            ax.bar([i - 0.2 for i in x], [r[key_off] for r in rows], 0.4, color="0.6", label="off")
            ax.bar([i + 0.2 for i in x], [r[key_on] for r in rows], 0.4, color="tab:orange", label="on")
            ax.set_xticks(list(x), [r["path"] for r in rows])
            ax.set_ylabel("GPU frame ms (median)")
            title = label
            if panel == "ibl":
                title += f" (prefilter once: {run['ibl']['prefilter_ms_median']:.0f} ms)"
            ax.set_title(title)
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=7)
    fig.suptitle(f"What each effect costs: {tag} (lavapipe; ratios within one run)")
    fig.tight_layout()
    fig.savefig(out / f"effects-{tag}.png", dpi=100)
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
    if (out / "shade-rate.json").exists():
        for run in json.loads((out / "shade-rate.json").read_text())["runs"]:
            plot_shade_rate(run, out)
        found = True
    if (out / "graph.json").exists():
        plot_graph(json.loads((out / "graph.json").read_text()), out)
        found = True
    if (out / "effects.json").exists():
        for run in json.loads((out / "effects.json").read_text())["runs"]:
            plot_effects(run, out)
        found = True
    if not found:
        sys.exit(f"plot_bench.py: no results.json, materials.json, shade-rate.json, graph.json or effects.json in {out}")
    print(f"wrote plots to {out}")


if __name__ == "__main__":
    main()
