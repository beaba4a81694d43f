#!/usr/bin/env python3
"""Per method, the real-hole and ring-removal figures of a run on open meshes, beside the
punched CAD holes of another results file, and Spearman's rho between the two rankings.

    scripts/real_hole_rankings.py REAL_HOLES_RESULTS [PUNCHED_RESULTS]

REAL_HOLES_RESULTS: a run on file/<stem>/hole/... cases (docs/generators.md, "Real holes"),
e.g. `holebench run --mesh DIR --no-cad --case 'file/*' --out RUN`, then RUN/results.json.
PUNCHED_RESULTS (default results/baselines/nightly.json): its cad/* jobs at noise 0, no_user.
Methods are ranked by the median hole_mean_distance_rel_diag of the punched holes and by the
median ring_mean_distance_rel_diag of the ring-removal cases (the unbiased direction). Python's
standard library only.
"""
import json
import os
import statistics
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def ranks(values):
    order = sorted(range(len(values)), key=lambda i: values[i])
    result = [0.0] * len(values)
    i = 0
    while i < len(order):
        j = i
        while j + 1 < len(order) and values[order[j + 1]] == values[order[i]]:
            j += 1
        for k in range(i, j + 1):
            result[order[k]] = (i + j) / 2 + 1
        i = j + 1
    return result


def spearman(a, b):
    ra, rb = ranks(a), ranks(b)
    ma, mb = statistics.mean(ra), statistics.mean(rb)
    num = sum((x - ma) * (y - mb) for x, y in zip(ra, rb))
    den = (sum((x - ma) ** 2 for x in ra) * sum((y - mb) ** 2 for y in rb)) ** 0.5
    return num / den if den else float("nan")


def median(rows, name):
    values = [r["metrics"][name] for r in rows if name in r["metrics"]]
    return statistics.median(values) if values else float("nan")


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    real = json.load(open(sys.argv[1]))["results"]
    punched_path = sys.argv[2] if len(sys.argv) > 2 else os.path.join(
        ROOT, "results/baselines/nightly.json")
    punched_all = json.load(open(punched_path))["results"]
    methods = sorted({r["method"] for r in real})
    print("| method | punched CAD: hole mean (n) | rings-1: ring mean | rings-2 | rings-4 "
          "| all rings | real: normal jump mean deg | real: dihedral mean deg "
          "| real: min triangle quality | real: patch self-intersections | real: ok / valid |")
    print("| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |")
    punched_rank, ring_rank = [], []
    for method in methods:
        rows = [r for r in real if r["method"] == method]
        holes = [r for r in rows if r["case_id"].split("/")[-1].isdigit()]
        rings = [r for r in rows if "/rings-" in r["case_id"]]
        punched = [r for r in punched_all if r["method"] == method and
                   r["case_id"].startswith("cad/") and r["noise_percent"] == 0 and
                   r["user"] == "no_user"]
        p = median(punched, "hole_mean_distance_rel_diag")
        by_rings = [median([r for r in rings if r["case_id"].endswith(f"/rings-{n}")],
                           "ring_mean_distance_rel_diag") for n in (1, 2, 4)]
        all_rings = median(rings, "ring_mean_distance_rel_diag")
        punched_rank.append(p)
        ring_rank.append(all_rings)
        ok = sum(r["status"] == "ok" for r in holes)
        valid = sum(r["metrics"].get("valid_repair_ok", 0) for r in holes)
        print(f"| {method} | {p:.5f} ({len(punched)}) | " +
              " | ".join(f"{v:.5f}" for v in by_rings) +
              f" | {all_rings:.5f} | {median(holes, 'patch_boundary_normal_jump_mean_deg'):.1f}"
              f" | {median(holes, 'patch_dihedral_mean_deg'):.1f}"
              f" | {median(holes, 'patch_triangle_quality_min_fraction'):.3f}"
              f" | {median(holes, 'patch_self_intersections_count'):.0f}"
              f" | {ok} / {valid:.0f} of {len(holes)} |")
    print(f"\nSpearman's rho, punched CAD ranking against ring-removal ranking "
          f"({len(methods)} methods): {spearman(punched_rank, ring_rank):.3f}")


if __name__ == "__main__":
    main()
