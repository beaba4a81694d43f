#!/usr/bin/python3
"""Draws the plots of `holebench report` from the numbers it computed.

Usage: /usr/bin/python3 scripts/plot_results.py PLOT_DATA_JSON OUT_DIR

PLOT_DATA_JSON is report/plots/plot_data.json as `holebench report` writes it (medians and
rates already computed; this script only draws). Writes into OUT_DIR:
  error_vs_noise.png   median hausdorff_rel_diag and hole_mean_distance_rel_diag against
                       the noise level, one line per method
  success_rate.png     fraction of jobs with status ok per case kind, one bar per method
  time_per_method.png  time_method_s per job, one box per method

The pictures are deterministic: fixed sizes and resolution, the Agg renderer, and no
software or time stamp in the PNG metadata. Exit status 3 when matplotlib is missing (Debian:
apt-get install python3-matplotlib), 2 on bad arguments.
"""

import json
import os
import sys

try:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError as error:  # the caller writes the report without plots
    print(f"plot_results.py: matplotlib is missing ({error})", file=sys.stderr)
    sys.exit(3)

DPI = 100
METADATA = {"Software": None}  # no version string or time stamp in the PNG


def method_colours(methods):
    palette = plt.get_cmap("tab10").colors
    return {m: palette[i % len(palette)] for i, m in enumerate(methods)}


def save(fig, path):
    # Written beside its place and renamed into it, as holebench writes its own files: a run
    # killed while drawing leaves the previous picture or none, never half of one.
    partial = path + ".partial"
    fig.savefig(partial, dpi=DPI, metadata=METADATA, format="png")
    plt.close(fig)
    os.replace(partial, path)


def positive(values):
    return [v for v in values if v is not None and v > 0]


def plot_error_vs_noise(data, colours, path):
    noise = data["noise_percent"]
    metrics = [
        ("hausdorff_rel_diag", "median Hausdorff distance / diagonal"),
        ("hole_mean_distance_rel_diag", "median hole mean distance / diagonal"),
    ]
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for ax, (metric, label) in zip(axes, metrics):
        per_method = data["error_vs_noise"].get(metric, {})
        drawn = False
        for method in data["methods"]:
            medians = per_method.get(method, [])
            points = [(x, y) for x, y in zip(noise, medians) if y is not None]
            if not points:
                continue
            xs, ys = zip(*points)
            ax.plot(xs, ys, marker="o", label=method, color=colours[method])
            drawn = True
        all_values = [v for m in per_method.values() for v in m if v is not None]
        if all_values and len(positive(all_values)) == len(all_values):
            ax.set_yscale("log")
        ax.set_xlabel("noise (% of 1 % of the diagonal)")
        ax.set_ylabel(label)
        ax.set_xticks(noise)
        ax.grid(True, alpha=0.3)
        if drawn:
            ax.legend(fontsize="small")
        else:
            ax.text(0.5, 0.5, "no values", ha="center", va="center", transform=ax.transAxes)
    fig.tight_layout()
    save(fig, path)


def plot_success_rate(data, colours, path):
    kinds = data["case_kinds"]
    methods = data["methods"]
    width = 0.8 / max(1, len(methods))
    fig, ax = plt.subplots(figsize=(max(6, 1.2 * len(kinds) + 2), 4))
    for i, method in enumerate(methods):
        rates = data["success_rate"].get(method, [])
        xs = [k + (i - (len(methods) - 1) / 2) * width for k in range(len(kinds))]
        ys = [r if r is not None else 0.0 for r in rates]
        ax.bar(xs, ys, width=width, label=method, color=colours[method])
    ax.set_xticks(range(len(kinds)))
    ax.set_xticklabels(kinds, rotation=30, ha="right")
    ax.set_ylim(0, 1.05)
    ax.set_ylabel("fraction of jobs with status ok")
    ax.grid(True, axis="y", alpha=0.3)
    ax.legend(fontsize="small", loc="upper left", bbox_to_anchor=(1.01, 1.0))
    fig.tight_layout()
    save(fig, path)


def plot_time(data, colours, path):
    methods = [m for m in data["methods"] if data["time_method_s"].get(m)]
    fig, ax = plt.subplots(figsize=(max(6, 1.2 * len(methods) + 2), 4))
    if methods:
        values = [data["time_method_s"][m] for m in methods]
        boxes = ax.boxplot(values, patch_artist=True)
        for patch, method in zip(boxes["boxes"], methods):
            patch.set_facecolor(colours[method])
        ax.set_xticks(range(1, len(methods) + 1))
        ax.set_xticklabels(methods, rotation=30, ha="right")
        flat = [v for vs in values for v in vs]
        if flat and min(flat) > 0 and max(flat) / min(flat) > 100:
            ax.set_yscale("log")
    else:
        ax.text(0.5, 0.5, "no times", ha="center", va="center", transform=ax.transAxes)
    ax.set_ylabel("method wall time per job (s)")
    ax.grid(True, axis="y", alpha=0.3)
    fig.tight_layout()
    save(fig, path)


def main(argv):
    if len(argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    with open(argv[1], encoding="utf-8") as f:
        data = json.load(f)
    out_dir = argv[2]
    os.makedirs(out_dir, exist_ok=True)
    plt.rcParams.update({"svg.hashsalt": "holebench", "font.size": 9})
    colours = method_colours(data["methods"])
    plot_error_vs_noise(data, colours, os.path.join(out_dir, "error_vs_noise.png"))
    plot_success_rate(data, colours, os.path.join(out_dir, "success_rate.png"))
    plot_time(data, colours, os.path.join(out_dir, "time_per_method.png"))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
