#!/usr/bin/env python3
"""Tests of the Python module `holebench` against the command line's files.

HOLEBENCH_TEST_WORK names the folder python_module_test.sh filled: run/ (a liepa_cgal run on
cad/fandisk/edge_convex/small and box/corner at noise 0 and 5, with --repaired-meshes), cases/
(the cases exported at noise 0) and fandisk_pair.json (`holebench evaluate --complete
--repaired --holed --json` on the fandisk's exported meshes and the run's repair).
"""
import json
import math
import os
import unittest

import numpy as np

import holebench

WORK = os.environ["HOLEBENCH_TEST_WORK"]
FANDISK = "cad/fandisk/edge_convex/small"
FANDISK_DIR = os.path.join(WORK, "cases", "cad_fandisk_edge_convex_small")
FANDISK_REPAIR = os.path.join(WORK, "run", "repaired",
                              "cad_fandisk_edge_convex_small_liepa_cgal_no_user_0_0.ply")


def read_off(path):
    """An independent OFF reader (the export writes 17 significant digits: exact)."""
    with open(path) as f:
        words = f.read().split()
    assert words[0] == "OFF"
    n, m = int(words[1]), int(words[2])
    values = words[4:]
    vertices = np.array([float(x) for x in values[:3 * n]]).reshape(n, 3)
    faces = []
    at = 3 * n
    for _ in range(m):
        count = int(values[at])
        faces.append([int(x) for x in values[at + 1:at + 1 + count]])
        at += 1 + count
    return vertices, np.array(faces)


def stem(job_id):
    return job_id.replace("/", "_").replace("|", "_")


class Cases(unittest.TestCase):
    def test_list_cases_selects_by_pattern(self):
        ids = [entry["id"] for entry in holebench.list_cases(["box/*"], include_cad=False)]
        self.assertEqual(ids, ["box/face_interior", "box/edge", "box/corner"])
        with self.assertRaises(ValueError):
            holebench.list_cases(["no/such/case"], include_cad=False)

    def test_suite_lists_its_cases_and_instances(self):
        smoke = holebench.suite("smoke")
        self.assertEqual(smoke["noise_percent"], [0.0, 5.0])
        self.assertIn("box/corner", smoke["cases"])
        self.assertTrue(all(not case.startswith("cad/") for case in smoke["cases"]))

    def test_make_case_equals_the_export(self):
        case = holebench.make_case(FANDISK)
        with open(os.path.join(FANDISK_DIR, "case.json")) as f:
            exported = json.load(f)
        exported.pop("files")
        self.assertEqual({k: v for k, v in case.items() if k not in ("input", "complete")},
                         exported)
        for name in ("input", "complete"):
            vertices, faces = read_off(os.path.join(FANDISK_DIR, name + ".off"))
            self.assertEqual(case[name]["vertices"].dtype, np.float64)
            self.assertEqual(case[name]["vertices"].shape, vertices.shape)
            self.assertTrue(np.array_equal(case[name]["vertices"], vertices))
            self.assertTrue(np.array_equal(case[name]["faces"], faces))
            if "regions" in case[name]:  # B-Rep faces; a CAD mesh's input has none
                self.assertEqual(case[name]["regions"].shape, (len(faces),))

    def test_labels_match_the_construction(self):
        case = holebench.make_case("box/corner")
        (hole,) = case["holes"]
        self.assertEqual(hole["labels"]["k"], 3)
        self.assertEqual(hole["labels"]["transitions"], ["convex"] * 3)
        self.assertEqual(len(hole["missing_corners"]), 1)
        removed = len(case["complete"]["faces"]) - len(case["input"]["faces"])
        self.assertEqual(len(hole["removed_faces"]), removed)

    def test_same_id_and_seed_give_the_same_case_bit_for_bit(self):
        first = holebench.make_case("box/corner", seed=3, noise_percent=5)
        again = holebench.make_case("box/corner", seed=3, noise_percent=5)
        clean = holebench.make_case("box/corner", seed=3, noise_percent=0)
        self.assertEqual(first["input"]["vertices"].tobytes(), again["input"]["vertices"].tobytes())
        self.assertFalse(np.array_equal(first["input"]["vertices"], clean["input"]["vertices"]))
        self.assertTrue(np.array_equal(first["complete"]["vertices"],
                                       clean["complete"]["vertices"]))


class Evaluate(unittest.TestCase):
    def test_the_pair_equals_the_command_line(self):
        with open(os.path.join(WORK, "fandisk_pair.json")) as f:
            cli = json.load(f)
        complete = os.path.join(FANDISK_DIR, "complete.ply")
        holed = os.path.join(FANDISK_DIR, "input.ply")
        by_path = holebench.evaluate(complete, FANDISK_REPAIR, holed=holed)
        by_arrays = holebench.evaluate(holebench.read_mesh(complete),
                                       holebench.read_mesh(FANDISK_REPAIR),
                                       holed=holebench.read_mesh(holed))
        for result in (by_path, by_arrays):
            self.assertEqual(result["metrics"], cli["metrics"])
            for key in ("holes", "removed_faces", "new_faces", "complete_bounding_box_diagonal"):
                self.assertEqual(result[key], cli[key])
        self.assertEqual(by_path["holes"], 1)
        self.assertGreater(by_path["metrics"]["hole_hausdorff_rel_diag"], 0.0)

    def test_a_case_repair_scores_as_in_the_run(self):
        records = {row["job_id"]: row for row in holebench.read_results(os.path.join(WORK, "run"))}
        self.assertEqual(len(records), 4)
        for job_id, row in records.items():
            case_id, _, _, noise, seed = job_id.split("|")
            case = holebench.make_case(case_id, seed=int(seed), noise_percent=float(noise))
            repair = holebench.read_mesh(os.path.join(WORK, "run", "repaired",
                                                      stem(job_id) + ".ply"))
            scored = holebench.evaluate_case(case, repair)
            self.assertEqual(scored["status"], "ok")
            metrics = scored["metrics"]
            run_metrics = {k: v for k, v in row.items()
                           if isinstance(v, float) and k not in ("noise_percent", "method_seconds")
                           and not k.startswith("time_")}
            self.assertEqual(set(metrics) - {k for k in metrics if k.startswith("time_")},
                             set(run_metrics), job_id)
            for name, value in run_metrics.items():
                # The patch's edges and new vertices are numbered as the file lists them, so a
                # sum over them may run in another order than in the run (last bits only).
                self.assertTrue(math.isclose(metrics[name], value, rel_tol=1e-12, abs_tol=1e-15),
                                f"{job_id} {name}: {metrics[name]} != {value}")

    def test_bad_input_is_a_value_error(self):
        case = holebench.make_case("box/corner")
        with self.assertRaisesRegex(ValueError, "faces must be an"):
            holebench.evaluate(case["complete"], (case["input"]["vertices"],
                                                  case["input"]["faces"][:, :2]))
        with self.assertRaisesRegex(ValueError, "names vertex"):
            holebench.evaluate(case["complete"], (case["input"]["vertices"],
                                                  case["input"]["faces"] + 10**6))
        moved = case["input"]["vertices"] + 1e-3
        with self.assertRaisesRegex(ValueError, "changed or dropped"):
            holebench.evaluate_case(case, (moved, case["input"]["faces"]))


class Results(unittest.TestCase):
    def test_rows_hold_every_record_and_metric(self):
        path = os.path.join(WORK, "run", "results.json")
        with open(path) as f:
            document = json.load(f)
        rows = holebench.read_results(path)
        self.assertEqual(len(rows), len(document["results"]))
        for row, record in zip(rows, document["results"]):
            self.assertEqual(row["case_id"], record["case_id"])
            self.assertEqual(row["status"], record["status"])
            for name, value in record["metrics"].items():
                self.assertEqual(row[name], value, name)


if __name__ == "__main__":
    unittest.main()
