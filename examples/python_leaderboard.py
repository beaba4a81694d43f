#!/usr/bin/env python3
"""holebench from Python: fill every case of a suite with a fan of triangles written in NumPy,
score each repair against the case's ground truth, and print a leaderboard beside the methods
of a results file (by default the smoke suite's reviewed baseline).

    PYTHONPATH=build/release/python python3 examples/python_leaderboard.py \
        [--suite smoke] [--results results/baselines/smoke.json]

Needs the module built (scripts/build.sh) and NumPy (Debian: python3-numpy). The fill is the
whole "method": six lines of NumPy in `fan_fill`; the rest is the loop a researcher writes
around their own method (docs/python.md).
"""
import argparse
import os
import statistics
import sys

import numpy as np

import holebench

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def boundary_loops(faces):
    """The boundary loops of a triangle mesh, each a list of vertex ids in the order its faces
    traverse them (the patch must traverse them the other way)."""
    edges = np.concatenate([faces[:, [0, 1]], faces[:, [1, 2]], faces[:, [2, 0]]])
    present = {(int(a), int(b)) for a, b in edges}
    following = {a: b for a, b in present if (b, a) not in present}
    loops = []
    while following:
        start, vertex = next(iter(following.items()))
        loop = [start]
        del following[start]
        while vertex != start and vertex in following:
            loop.append(vertex)
            vertex = following.pop(vertex)
        loops.append(loop)
    return loops


def fan_fill(mesh):
    """Closes every boundary loop with a fan around the centroid of its vertices."""
    vertices, faces = mesh["vertices"], mesh["faces"]
    new_vertices, new_faces = [vertices], [faces]
    for loop in boundary_loops(faces):
        centre = len(vertices) + len(new_vertices) - 1
        new_vertices.append(vertices[loop].mean(axis=0, keepdims=True))
        new_faces.append(np.array([[centre, b, a] for a, b in zip(loop, loop[1:] + loop[:1])]))
    return np.concatenate(new_vertices), np.concatenate(new_faces)


def leaderboard(rows):
    """Per method: jobs, valid repairs, median hole Hausdorff and hole mean distance."""
    by_method = {}
    for row in rows:
        by_method.setdefault(row["method"], []).append(row)
    table = []
    for method, jobs in by_method.items():
        valid = sum(row.get("valid_repair_ok", 0.0) for row in jobs)
        hausdorff = [row["hole_hausdorff_rel_diag"] for row in jobs
                     if "hole_hausdorff_rel_diag" in row]
        mean = [row["hole_mean_distance_rel_diag"] for row in jobs
                if "hole_mean_distance_rel_diag" in row]
        table.append((method, len(jobs), valid / len(jobs),
                      statistics.median(hausdorff) if hausdorff else float("nan"),
                      statistics.median(mean) if mean else float("nan")))
    table.sort(key=lambda entry: (-entry[2], entry[3]))
    print("| method | jobs | valid repairs | median hole Hausdorff / diag "
          "| median hole mean distance / diag |")
    print("| --- | ---: | ---: | ---: | ---: |")
    for method, jobs, valid, hausdorff, mean in table:
        print(f"| {method} | {jobs} | {valid:.0%} | {hausdorff:.5f} | {mean:.6f} |")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--suite", default="smoke", help="a suite name or file (default smoke)")
    parser.add_argument("--results", default=os.path.join(ROOT, "results/baselines/smoke.json"),
                        help="the results file whose methods stand beside the fan "
                             "(default: the smoke suite's baseline)")
    args = parser.parse_args()

    suite = holebench.suite(args.suite)
    instances = [(case_id, noise, seed) for case_id in suite["cases"]
                 for noise in suite["noise_percent"] for seed in suite["seeds"]]
    rows = []
    for number, (case_id, noise, seed) in enumerate(instances, 1):
        case = holebench.make_case(case_id, seed=seed, noise_percent=noise)
        vertices, faces = fan_fill(case["input"])
        scored = holebench.evaluate_case(case, (vertices, faces))
        rows.append(dict(method="numpy_fan", case_id=case_id, noise_percent=noise, seed=seed,
                         status=scored["status"], **scored["metrics"]))
        print(f"[{number}/{len(instances)}] {case_id} noise {noise}: {scored['status']}, "
              f"hole Hausdorff {scored['metrics'].get('hole_hausdorff_rel_diag', float('nan')):.5f}",
              file=sys.stderr)

    wanted = set(instances)
    others = [row for row in holebench.read_results(args.results)
              if (row["case_id"], row["noise_percent"], row["seed"]) in wanted
              and row["user"] == "no_user"]
    leaderboard(rows + others)


if __name__ == "__main__":
    main()
