#!/usr/bin/python3
"""Unit tests of scripts/plot/measures: the numbers the report and claims.md set against the thesis,
computed from hand-made data frames and tiny tables whose answers are known.
Usage: measures_test.py <source dir>"""
import math
import os
import sys
import unittest

sys.path.insert(0, os.path.join(sys.argv[1] if len(sys.argv) > 1 else ".", "scripts", "plot"))
import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402

from measures import common, compare, planes  # noqa: E402


def iterations(values, column="position_error", start=0):
    return pd.DataFrame({"iteration": np.arange(start, start + len(values)), column: values})


class Compare(unittest.TestCase):
    def test_ratio_rows_are_dropped_and_rows_indexed_by_algorithm(self):
        summary = pd.DataFrame({"algorithm": ["relative_point", "ekf6d", "relative_point/ekf6d"],
                                "status": ["ok", "ok", "ratio"], "runtime_median_ms": [1.0, 50.0, 0.02]})
        rows = compare.algorithm_rows(summary)
        self.assertEqual(list(rows.index), ["relative_point", "ekf6d"])
        self.assertEqual(compare.times_faster(rows, "relative_point", "ekf6d"), 50.0)
        self.assertTrue(math.isnan(compare.times_faster(rows, "relative_point", "ekf2d")))

    def test_bands_are_symmetric_in_the_ratio(self):
        for r, want in [(1.0, "holds"), (2.0, "holds"), (0.5, "holds"), (3.0, "partly"), (1 / 3, "partly"),
                        (4.5, "does not hold"), (0.2, "does not hold"), (float("nan"), "does not hold"),
                        (0.0, "does not hold")]:
            self.assertEqual(compare.band(r), want, r)

    def test_comparable_uses_only_the_iterations_both_processed(self):
        rel = iterations([1.0, 1.0, 1.0, 1.0, 100.0])  # the last iteration only Relative processed
        ekf = iterations([2.0, 2.0, 2.0, 2.0])
        verdict, r, n = compare.comparable(rel, ekf, "position_error")
        self.assertEqual((verdict, n), ("holds", 4))
        self.assertAlmostEqual(r, 0.5)

    def test_nan_iterations_are_skipped(self):
        rel = iterations([1.0, float("nan"), 1.0])
        ekf = iterations([8.0, 1.0, 8.0])
        verdict, r, n = compare.comparable(rel, ekf, "position_error")
        self.assertEqual((verdict, n, r), ("does not hold", 2, 1 / 8))

    def test_no_common_iteration_is_no_number(self):
        verdict, r, n = compare.comparable(iterations([1.0]), iterations([1.0], start=5), "position_error")
        self.assertEqual((verdict, n), ("does not hold", 0))
        self.assertTrue(math.isnan(r))

    def test_side_by_side_takes_the_statistic_over_shared_iterations(self):
        frames = {"relative_point": iterations([1.0, 3.0, 5.0, 7.0]), "ekf6d": iterations([2.0, 4.0])}
        rows, shared = compare.side_by_side(frames, "position_error", "mean")
        self.assertEqual(shared, 2)
        self.assertEqual(rows, [("relative_point", 4, 2.0, 7.0), ("ekf6d", 2, 3.0, 4.0)])
        rows, _ = compare.side_by_side(frames, "position_error", "median")
        self.assertEqual(rows[0][2], 2.0)

    def test_faster_verdict(self):
        self.assertEqual(compare.faster_verdict(1000.0, 100), "holds")
        self.assertEqual(compare.faster_verdict(5.0, 100), "partly")
        self.assertEqual(compare.faster_verdict(0.5, 100), "does not hold")


class Common(unittest.TestCase):
    def test_fits_recover_known_coefficients(self):
        n = np.arange(10.0, 1000.0, 10.0)
        self.assertAlmostEqual(common.fit_scale(n, 0.37 * common.n_log_n(n), common.n_log_n), 0.37, places=12)
        slope, intercept = common.line_fit(n, 3 * n - 7)
        self.assertAlmostEqual(slope, 3.0, places=9)
        self.assertAlmostEqual(intercept, -7.0, places=6)

    def test_steady_state(self):
        self.assertEqual(len(common.steady(np.arange(1000))), 1000 - common.STEADY_FROM)
        self.assertEqual(common.steady(np.arange(100))[0], 50)


class Planes(unittest.TestCase):
    def test_means_per_loop_cut_the_run_into_equal_loops(self):
        d = pd.DataFrame({"iteration": np.arange(10), "map_error": [1.0] * 5 + [3.0, float("nan"), 3.0, 3.0, 3.0]})
        self.assertEqual(planes.means_per_loop(d, "map_error", 2, 10), [(0, 4, 1.0), (5, 9, 3.0)])
        empty = pd.DataFrame({"iteration": np.arange(4), "map_error": [float("nan")] * 4})
        self.assertTrue(all(math.isnan(m) for _, _, m in planes.means_per_loop(empty, "map_error", 2, 4)))

    def test_error_events_find_a_jump_and_when_it_heals(self):
        error = [0.0] * 8 + [1.0, 0.9, 0.5, 0.1, 0.0, 0.0]  # a jump of 1 at iteration 8, back under 0.25 after 3
        planes_in_map = [3] * 8 + [4] * 6
        d = pd.DataFrame({"iteration": np.arange(len(error)), "map_error": error, "planes_in_map": planes_in_map})
        self.assertEqual(planes.error_events(d), [(8, 1.0, 3, True)])
        never = d.assign(map_error=[0.0] * 8 + [1.0] * 6)
        self.assertEqual(planes.error_events(never), [(8, 1.0, None, True)])
        small = d.assign(map_error=[0.0] * 8 + [planes.EVENT_JUMP / 2] * 6)
        self.assertEqual(planes.error_events(small), [])

    def test_wrap_deg_is_in_the_half_open_circle(self):
        for angle, want in [(0, 0), (190, -170), (-190, 170), (360, 0), (540, -180), (180, -180)]:
            self.assertAlmostEqual(float(planes.wrap_deg(angle)), want)

    def test_planar_rotation_is_a_rotation_by_the_angle(self):
        r = planes.planar_rotation(0.3)
        self.assertTrue(np.allclose(r @ r.T, np.eye(2)))
        self.assertAlmostEqual(float(np.linalg.det(r)), 1.0)
        self.assertTrue(np.allclose(r @ [1.0, 0.0], [math.cos(0.3), math.sin(0.3)]))


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1], verbosity=1)
