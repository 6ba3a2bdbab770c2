#!/usr/bin/python3
"""Unit tests of scripts/plot/measures: the numbers the report and claims.md set against the thesis,
computed from hand-made data frames and tiny tables whose answers are known (every measure claims.py
uses). Usage: measures_test.py <source dir>"""
import math
import os
import sys
import types
import unittest

sys.path.insert(0, os.path.join(sys.argv[1] if len(sys.argv) > 1 else ".", "scripts", "plot"))
import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402

from measures import common, compare, em, planes, points, verdicts  # noqa: E402
import relslam_plot as rp  # noqa: E402


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
        self.assertEqual(planes.map_error_events(d), [(8, 1.0, 3, True)])
        never = d.assign(map_error=[0.0] * 8 + [1.0] * 6)
        self.assertEqual(planes.map_error_events(never), [(8, 1.0, None, True)])
        small = d.assign(map_error=[0.0] * 8 + [planes.EVENT_JUMP / 2] * 6)
        self.assertEqual(planes.map_error_events(small), [])
        both = d.assign(map_error=[0.0] * 8 + [1.0, 0.9, 0.5, 0.1, 0.0, 1.0])  # healed in 3; a second never heals
        self.assertEqual(planes.event_healing(both), (2, 1, 1, 3.0))

    def test_wrap_deg_is_in_the_half_open_circle(self):
        for angle, want in [(0, 0), (190, -170), (-190, 170), (360, 0), (540, -180), (180, -180)]:
            self.assertAlmostEqual(float(planes.wrap_deg(angle)), want)

    def test_planar_rotation_is_a_rotation_by_the_angle(self):
        r = planes.planar_rotation(0.3)
        self.assertTrue(np.allclose(r @ r.T, np.eye(2)))
        self.assertAlmostEqual(float(np.linalg.det(r)), 1.0)
        self.assertTrue(np.allclose(r @ [1.0, 0.0], [math.cos(0.3), math.sin(0.3)]))

    def test_planar_track_reads_the_heading_from_the_quaternion(self):
        half = math.radians(90) / 2  # a turn by psi about -y: q = (0, -sin psi/2, 0, cos psi/2)
        t = tum([0.0, 1.0], [0.0, 2.0], [0.0, 3.0], qy=[0.0, -math.sin(half)], qw=[1.0, math.cos(half)])
        track = planes.planar_track(t)
        self.assertEqual(list(track["iteration"]), [0.0, 1.0])
        self.assertEqual(list(track["z"]), [0.0, 3.0])
        self.assertAlmostEqual(track["psi_deg"][0], 0.0)
        self.assertAlmostEqual(track["psi_deg"][1], 90.0)

    def test_run_loops_and_loop_means(self):
        r = types.SimpleNamespace(manifest=manifest(loops=2, iterations=10),
                                  iterations=iterations([1.0] * 5 + [2.0, 4.0, 2.0, 4.0, 3.0], "mean_map_error"))
        self.assertEqual(planes.run_loops(r.manifest), (2, 10))
        self.assertEqual(planes.loop_means(r, "mean_map_error"), [(0, 4, 1.0), (5, 9, 3.0)])
        with self.assertRaisesRegex(rp.DataError, "manifest.json: no scenario.planar.loops"):
            planes.run_loops({"scenario": {}})
        with self.assertRaisesRegex(rp.DataError, "loops is 0: no loops"):
            no_loops = types.SimpleNamespace(manifest=manifest(0, 10), iterations=r.iterations)
            planes.loop_means(no_loops, "mean_map_error")

    def test_invariance_turns_the_offset_into_the_first_plane_frame(self):
        # Two parallel walls one unit apart; the robot sees them at heading 0 and turned by 90 degrees.
        walls = frame(id=[0, 1], a_x=[0.0, 0.0], a_z=[0.0, 1.0], b_x=[2.0, 2.0], b_z=[0.0, 1.0])
        obs = frame(iteration=[0, 0, 1, 1], true_wall=[0, 1, 0, 1], kp1_x=[0.0, 0.0, 0.0, -1.0],
                    kp1_z=[0.0, 1.0, 0.0, 0.0], kp2_x=[2.0, 2.0, 0.0, -1.0], kp2_z=[0.0, 1.0, 2.0, 2.0])
        half = math.radians(90) / 2
        r = types.SimpleNamespace(observations=obs, walls=walls,
                                  truth_path=tum([0.0, 1.0], [0.0, 0.0], [0.0, 0.0], qy=[0.0, -math.sin(half)],
                                                 qw=[1.0, math.cos(half)]))
        psi, raw, rel, expected = planes.invariance(r)
        self.assertTrue(np.allclose(psi, [0.0, 90.0]))
        self.assertTrue(np.allclose(raw, [[0.0, 1.0], [-1.0, 0.0]]))  # the raw offset turns with the robot
        self.assertTrue(np.allclose(rel, [[0.0, 1.0], [0.0, 1.0]]))  # Rule 3's does not
        self.assertTrue(np.allclose(expected, [0.0, 1.0]))

    def test_group_counts_take_the_last_iteration(self):
        counts = planes.group_counts([("on", iterations([1, 2, 3], "groups")), ("off", iterations([1], "groups"))])
        self.assertEqual(counts, {"on": 3, "off": 1})

    def test_key_point_pair_scores_the_chosen_ends_against_the_truth(self):
        offsets = {f"off{a}{b}_{c}": [0.0, 0.0] for a in (1, 2) for b in (1, 2) for c in "xz"}
        pairs = frame(iteration=[5, 6], plane1=[1, 1], plane2=[2, 2], a1_x=[1.0, 1.0], a1_z=[0.0, 0.0],
                      a2_x=[3.0, 3.0], a2_z=[0.0, 0.0], **offsets)
        zeros = [0.0] * 4
        sigma = frame(kp_a=[1, 1, 2, 2], kp_b=[1, 2, 1, 2], sigma=[0.3, 0.1, 0.2, 0.4], mean_x=zeros, mean_z=zeros,
                      chosen=[0, 1, 0, 0], key_point1=[1] * 4, key_point2=[2] * 4, samples=[2] * 4,
                      interval_start=zeros, interval_end=zeros)
        obs = frame(iteration=[5, 5, 6, 6], kp1_x=[1.0, 3.0, 1.0, 3.0], kp1_z=zeros,
                    kp1_true_end=[1, 0, 0, 1], kp2_true_end=[0, 1, 0, 1])
        series, sig, chosen, right = planes.key_point_pair(types.SimpleNamespace(pairs=pairs, pair_sigma=sigma,
                                                                                 observations=obs))
        self.assertEqual(chosen, 1)
        self.assertEqual(planes.PAIR_NAMES[(int(sig["kp_a"][chosen]), int(sig["kp_b"][chosen]))], "KP1–KP2")
        self.assertEqual(right, [0.5, 1.0])  # plane 1's first end is a wall end once in two, plane 2's second always

    def test_interval_mode_errors_average_the_seeds(self):
        seeds = [iterations([1.0, 3.0, float("nan")], "mean_map_error"),
                 iterations([3.0, 5.0, 7.0, 9.0], "mean_map_error")]
        errors = planes.interval_mode_errors([(("group", "gauss"), seeds)])
        it, err, mean, n = errors[("group", "gauss")]
        self.assertEqual(list(it), [0, 1, 2])  # cut to the shortest seed
        self.assertEqual(list(err), [2.0, 4.0, 7.0])  # a NaN seed is left out of its iteration's mean
        self.assertEqual((mean, n), (13 / 3, 2))

    def test_wrong_key_point_episodes_and_healing(self):
        rows = [(1, 1, i, 0 if i in (2, 3, 5, 6, 7, 8, 9) else 1) for i in range(10)] + [(2, 3, 0, 0), (2, 3, 1, 1)]
        k = frame(group=[r[0] for r in rows], plane=[r[1] for r in rows], iteration=[r[2] for r in rows],
                  truth_correct=[r[3] for r in rows])
        self.assertEqual(planes.wrong_episodes(k), [(1, 1, 5, 5), (1, 1, 2, 2), (2, 3, 0, 1)])
        self.assertEqual(planes.healing(k), (3, 2.0, 2 / 3, 5))
        self.assertEqual(planes.healing(k[k["truth_correct"] == 1])[0], 0)

    def test_plane_table_measures(self):
        p = frame(id=[1, 2, 3, 4], true_wall=[0, 0, 1, float("nan")], len_ratio=[0.5, 0.97, 0.9, 0.1],
                  e_ends=[0.1, 0.2, 0.3, 0.4], e_perp=[0.0, 1e-9, 0.01, 5.0], length=[1.0, 1.9, 0.8, 7.0])
        self.assertEqual(planes.wall_table(p), {0: [(0.5, 0.1), (0.97, 0.2)], 1: [(0.9, 0.3)]})
        self.assertEqual(planes.under_sized(p), [(1, 0.9)])
        self.assertEqual(planes.misplaced(p), [(1, 0.01)])
        self.assertEqual(planes.mapped_length(p, 0), 1.9)
        self.assertTrue(math.isnan(planes.mapped_length(p, 7)))
        e = frame(valid=[1, 1, 0], length1=[1.0, 1.0, 1.0], length2=[1.0, 1.0, 1.0], canonical1=[1.0, 1.5, 3.0],
                  canonical2=[1.0, 1.0, 1.0])
        self.assertEqual(planes.size_mismatches(e), (1, 3, 2.0))

    def test_count_summary_is_the_relative_plane_row(self):
        s = frame(algorithm=["ekf6d", "relative_plane"], final_mean_map_error=[9.0, 0.25], walls_mapped=[0, 4],
                  walls_seen=[0, 5], duplicates=[0, 1], pose_valid_fraction=[0.0, 0.5])
        self.assertEqual(planes.count_summary(s), {"final_mean_map_error": 0.25, "walls_mapped": 4.0, "walls_seen": 5.0,
                                                   "duplicates": 1.0, "pose_valid_fraction": 0.5})
        with self.assertRaisesRegex(rp.DataError, "no relative_plane row"):
            planes.count_summary(s.iloc[:1])

    def test_revisit_time_sums_the_steps_after_the_robot_is_back(self):
        path = tum([0, 1, 2, 3, 4], [0.0, 6.0, 3.0, 0.5, 0.2], [0.0] * 5)
        r = types.SimpleNamespace(truth_path=path, iterations=iterations([1.0, 2.0, 3.0, 4.0, 5.0], "runtime_ms"))
        self.assertEqual(planes.revisit_time(r), (9.0, 3))
        r.truth_path = tum([0, 1, 2, 3, 4], [0.0, 6.0, 7.0, 8.0, 9.0], [0.0] * 5)  # never back
        self.assertIsNone(planes.revisit_time(r))

    def test_collinear_run(self):
        d = frame(iteration=[0, 1, 2], map_error=[0.0, 0.5, 1.0], position_error=[0.0, 0.0, 1e-3],
                  pose_valid=[1, 1, 1], kp_wrong=[0, 0, 0])
        r = types.SimpleNamespace(iterations=d, keypoints=frame(iteration=[0, 1, 2], ambiguous=[0, 1, 1]),
                                  edges=frame(ambiguous=[1, 0]))
        _, first_bad, claims, edges = planes.collinear_run(r)
        self.assertEqual((first_bad, claims, edges), (2, 2, 1))

    def test_runtime_by_size(self):
        runs = [("2", frame(runtime_ms=list(range(1, 11)), rlt_planes=[3] * 9 + [7])), ("1", frame(runtime_ms=[4.0],
                                                                                                      rlt_planes=[1]))]
        self.assertEqual(planes.runtime_by_size(runs), {1: (4.0, 4.0, 4.0, 1, 1), 2: (5.5, 1.0, 10.0, 7, 10)})

    def test_first_corner_motion_model_and_turn(self):
        r = corner_run()
        self.assertEqual(list(planes.turn_iterations(r.truth_path)), [2, 3, 4])
        episodes = planes.mm_episodes(r)
        self.assertEqual(episodes, [{"first": 1, "last": 3, "plane": 7, "wall": 3, "true_length": 2.0,
                                     "start_length": 1.0, "length": 2.0}])
        e, before, heading = planes.first_corner(r)
        self.assertEqual((e["first"], before), (1, 1.0))  # one unit of path before the turn
        self.assertAlmostEqual(heading, 45.0)  # it ends halfway through the turn
        self.assertEqual(planes.key_points_by_phase(frame(kp_checked=[2, 2, 2], kp_wrong=[1, 0, 1],
                                                          mm_active=[1, 0, 1])), {"in": (2, 4), "out": (0, 2)})
        tracked, mapped, seeds = planes.grown_lengths([("v", [r])])["v"]
        self.assertEqual((list(tracked), list(mapped), seeds), ([1.0], [0.9], 1))
        self.assertEqual(planes.motion_model_exits(r), (1, 1, 2))  # it ends in group 0, made before it

    def test_frustum_turns_find_the_end_wall_of_the_turn(self):
        r = corner_run()
        frustum, shape, wall, seen, mapped, true = planes.frustum_turns([("v", r)])["v"]
        self.assertEqual((frustum, shape, wall, mapped, true), ("planar", "flat", 3, 1.8, 2.0))
        self.assertEqual(list(seen["iteration"]), [2, 3, 4])
        self.assertEqual(list(seen["length"]), [1.0, 1.0, 1.0])
        self.assertAlmostEqual(seen["range"][0], math.sqrt(5))
        self.assertTrue(np.allclose(seen["psi_deg"], [0.0, 45.0, 90.0]))

    def test_one_plane_iteration_is_in_the_last_loop(self):
        r = types.SimpleNamespace(manifest=manifest(2, 6), iterations=frame(
            iteration=list(range(6)), mm_active=[1, 0, 0, 1, 1, 1], visible_planes=[1, 1, 1, 1, 1, 2]))
        self.assertEqual(planes.one_plane_iteration(r), (4, 3, 4))


class Points(unittest.TestCase):
    def test_density_table_means_the_steady_state_over_seeds(self):
        def run(runtime, visible):
            return frame(runtime_ms=runtime, visible_points=visible, t_init_ms=[0.5] * 4, t_load_ms=[0.25] * 4,
                         t_compute_ms=[0.0] * 4, t_create_ms=[0.25] * 4)
        # short runs keep their second half: (1 + 3) / 2 and (3 + 5) / 2 average to 3 over the two seeds
        t = points.density_table([(50.0, run([9, 9, 7, 7], [1, 1, 2, 2])), (25.0, run([9, 9, 1, 3], [5, 5, 5, 5])),
                                  (25.0, run([9, 9, 3, 5], [5, 5, 7, 7]))])
        self.assertEqual(list(t["density"]), [25.0, 50.0])
        self.assertEqual(list(t["runtime_ms"]), [3.0, 7.0])
        self.assertEqual(list(t["visible_points"]), [6.0, 2.0])
        self.assertEqual(list(t["t_other_ms"]), [2.0, 6.0])

    def test_vp_benchmarks_keep_the_mean_of_repetitions(self):
        doc = {"benchmarks": [
            {"label": "levels 2, window all", "ms_per_scan": 1.5},
            {"label": "levels 3, window all", "run_type": "iteration", "repetitions": 3, "ms_per_scan": 9.0},
            {"label": "levels 3, window all", "run_type": "aggregate", "aggregate_name": "mean", "ms_per_scan": 2.0},
            {"label": "levels 3, window all", "run_type": "aggregate", "aggregate_name": "stddev", "ms_per_scan": 0.1},
            {"label": "levels 1, window 1181:1642", "ms_per_scan": 0.5}]}
        self.assertEqual(points.vp_benchmarks(doc), {"all": {2: 1.5, 3: 2.0}, "1181:1642": {1: 0.5}})
        with self.assertRaisesRegex(rp.DataError, "vp.json: no benchmark"):
            points.vp_benchmarks({"benchmarks": []}, "vp.json")


class Em(unittest.TestCase):
    def test_demo_times_and_compare_frames(self):
        times = em.demo_times({"a": frame(t_extract_ms=[1.0, 2.0], runtime_ms=[0.5, 0.25])})
        self.assertEqual({k: (list(a), list(b)) for k, (a, b) in times.items()}, {"a": ([1.0, 2.0], [0.5, 0.25])})
        columns = {f"{c}_{e}": [v, v] for e, v in (("em1", 2.0), ("em2", 1.0))
                   for c in ("ms", "recall", "precision", "n_planes", "mean_normal_err_deg")}
        it, by = em.compare_frames(frame(iteration=[0, 1], **columns))
        self.assertEqual(list(by), ["em2", "em1"])  # EXTRACTORS order, only those present
        self.assertEqual(list(by["em1"]["ms"]), [2.0, 2.0])
        with self.assertRaisesRegex(rp.DataError, "no ms_<extractor> column"):
            em.compare_frames(frame(iteration=[0]))


class Loaded(unittest.TestCase):
    def test_arrays_name_the_file_of_a_missing_column(self):
        f = frame(a=[1, 2], s=["x", float("nan")])
        f.attrs["path"] = "run/planes.csv"
        got = common.arrays(f, ["a", "s"], strings=("s",))
        self.assertEqual((list(got["a"]), list(got["s"])), ([1.0, 2.0], ["x", ""]))
        with self.assertRaisesRegex(rp.DataError, r"run/planes.csv: missing column\(s\) b"):
            common.arrays(f, ["a", "b"])

    def test_seed_means_cut_to_the_shortest(self):
        means = common.seed_means([{"iteration": [0, 1, 2], "x": [1, 2, 3]}, {"iteration": [0, 1], "x": [3, 4]}],
                                  ["iteration", "x"])
        self.assertEqual((list(means["iteration"]), list(means["x"])), ([0.0, 1.0], [2.0, 3.0]))


def frame(**columns):
    return pd.DataFrame(columns)


def tum(t, x, z, qy=None, qw=None):
    n = len(t)
    return frame(t=t, x=x, y=[0.0] * n, z=z, qx=[0.0] * n, qy=qy or [0.0] * n, qz=[0.0] * n, qw=qw or [1.0] * n)


def manifest(loops, iterations):
    return {"scenario": {"planar": {"loops": loops, "frustum": "planar", "frustum_shape": "flat"}},
            "planar_simulation": {"iterations": iterations}}


def corner_run():
    """Six iterations: one unit along x, then a turn in place by 90 degrees over iterations 2-4; a motion
    model on plane 7 (wall 3, two units long) over iterations 1-3 that tracks it from 1 to 2 units; the end
    wall seen from (0, 2)-(1, 2) throughout the turn."""
    psi = [0.0, 0.0, 0.0, 45.0, 90.0, 90.0]
    qy = [-math.sin(math.radians(p) / 2) for p in psi]
    qw = [math.cos(math.radians(p) / 2) for p in psi]
    nan = float("nan")
    return types.SimpleNamespace(
        truth_path=tum(list(range(6)), [0.0, 1.0, 2.0, 2.0, 2.0, 2.0], [0.0] * 6, qy, qw),
        iterations=frame(iteration=list(range(6)), mm_active=[0, 1, 1, 1, 0, 0], mm_plane=[nan, 7, 7, 7, nan, nan],
                         mm_s_min=[nan, 0.0, 0.0, 0.0, nan, nan], mm_s_max=[nan, 1.0, 1.5, 2.0, nan, nan],
                         current_group=[0, 0, 1, 1, 0, 0]),
        planes=frame(id=[7], true_wall=[3], len_ratio=[0.9], length=[1.8]),
        walls=frame(id=[3], length=[2.0]),
        groups=frame(group_id=[0, 1], created_iter=[0, 2]),
        observations=frame(iteration=[2, 3, 4, 4], true_wall=[3, 3, 3, 5], kp1_x=[0.0] * 4, kp1_z=[2.0] * 4,
                           kp2_x=[1.0] * 4, kp2_z=[2.0] * 4),
        manifest=manifest(1, 6))


class DescribeAxes(unittest.TestCase):
    """A figure without its own "what our run shows" is described from the series it drew."""

    def test_series_maps_fits_and_reference_lines(self):
        from matplotlib.figure import Figure
        import draw
        fig = Figure()
        ax = fig.subplots()
        ax.plot([0, 1, 2, 3], [1.0, 3.0, 2.0, 6.0], label="Relative Point")
        ax.plot([0, 2, 1], [0.0, 1.0, 4.0], label="path")          # not monotonic in x: a path
        ax.plot([0, 3], [2.0, 2.0], label="c·n fit, c = 0.5")
        ax.axhline(0.0)                                             # an unlabelled reference line
        ax.scatter([0.0, 1.0, 5.0], [0.0, 2.0, 1.0], label="landmarks")
        ax.set_ylabel("error")
        self.assertEqual(draw.describe_axes(fig),
                         "Relative Point: mean 3, from 1 to 6, last 6 (4 points); path: 3 points over 2 × 4; "
                         "c·n fit, c = 0.5; landmarks: 3 points")


H, P, N = verdicts.HOLDS, verdicts.PARTLY, verdicts.DOES_NOT


class Verdicts(unittest.TestCase):
    """Each claim's verdict from hand-picked numbers on both sides of its thresholds."""

    def verdict(self, result):
        verdict, parts = result
        self.assertTrue(parts, "a verdict names what it checked")
        return verdict

    def test_parts_combine_into_holds_partly_does_not(self):
        self.assertEqual(verdicts.of_parts([("a", True), ("b", True)]), H)
        self.assertEqual(verdicts.of_parts([("a", True), ("b", False)]), P)
        self.assertEqual(verdicts.of_parts([("a", False)]), N)
        self.assertEqual(verdicts.of_parts([]), N)
        self.assertEqual(verdicts.text((H, [("x 1", True), ("y 2", False)])), "x 1: yes; y 2: no")

    def test_times_are_budgets_and_shares_bounds(self):
        for ours, want in [(0.5, H), (2.0, H), (3.9, P), (4.1, N), (float("nan"), N)]:
            self.assertEqual(self.verdict(verdicts.within_time(ours, 2.0)), want, ours)
        for ours, want in [(1.5, H), (3.0, P), (6.7, N)]:
            self.assertEqual(self.verdict(verdicts.within_share(ours, 2.0)), want, ours)

    def test_a_ratio_must_lie_on_the_thesis_side_of_one(self):
        self.assertEqual(self.verdict(verdicts.same_ratio(0.0691, 0.028, 7.8, 2.5)), H)  # 2.47 vs 3.12
        self.assertEqual(self.verdict(verdicts.same_ratio(10.0, 1.0, 7.8, 2.5)), P)      # 10 vs 3.12
        self.assertEqual(self.verdict(verdicts.same_ratio(0.0722, 0.0638, 1.3, 4.5)), N)  # 1.13 vs 0.29
        self.assertEqual(self.verdict(verdicts.same_ratio(1.0, 0.0, 7.8, 2.5)), N)  # no ratio

    def test_rule3_offset_constant_and_true(self):
        self.assertEqual(self.verdict(verdicts.rule3_invariance([2.0, 5.0], [0.02, 0.03], [-6.001, 4.0], [-6, 4])), H)
        self.assertEqual(self.verdict(verdicts.rule3_invariance([2.0, 5.0], [0.5, 0.03], [-6.0, 4.0], [-6, 4])), P)
        self.assertEqual(self.verdict(verdicts.rule3_invariance([2.0, 5.0], [0.5, 0.5], [-3.0, 4.0], [-6, 4])), N)

    def test_completed_map(self):
        self.assertEqual(self.verdict(verdicts.completed_map(36, 36, 1.5e-14, 1.0)), H)
        self.assertEqual(self.verdict(verdicts.completed_map(35, 36, 1.5e-14, 1.0)), P)
        self.assertEqual(self.verdict(verdicts.completed_map(35, 36, 0.2, 0.5)), N)

    def test_rule21_group_counts(self):
        self.assertEqual(self.verdict(verdicts.rule21_groups(21, 30, 25)), H)
        self.assertEqual(self.verdict(verdicts.rule21_groups(10, 12, 12)), P)
        self.assertEqual(self.verdict(verdicts.rule21_groups(12, 10, 10)), N)
        self.assertEqual(self.verdict(verdicts.identical(4.4e-15)), H)
        self.assertEqual(self.verdict(verdicts.identical(1e-3)), N)

    def test_em_bench_failures_and_defaults(self):
        scores = {"close": {"em2": (0.0, 0.0), "em1": (1.0, 1.0)}, "nearest": {"em2": (1.0, 1.0), "em1": (1.0, 1.0)},
                  "defaults": {"em2": (1.0, 1.0), "em1": (1.0, 1.0)}}
        self.assertEqual(self.verdict(verdicts.em_bench(scores, ["close"], ["defaults"])), H)
        self.assertEqual(self.verdict(verdicts.em_bench(scores, ["close", "nearest"], ["defaults"])), P)
        self.assertEqual(self.verdict(verdicts.em_bench(scores, ["nearest"], ["close"])), N)

    def test_em2_speed_decides(self):
        self.assertEqual(self.verdict(verdicts.em2_speed([2.1, 1.8], [0.0, 0.01])), H)
        self.assertEqual(self.verdict(verdicts.em2_speed([1.2, 1.8], [0.0, 0.01])), P)
        self.assertEqual(self.verdict(verdicts.em2_speed([1.03, 0.79], [0.0, 0.0])), N)  # similar quality, slower

    def test_moving_average_window(self):
        free = {"w_ma_3": (0.1, 21), "w_ma_5": (0.2, 21)}
        self.assertEqual(self.verdict(verdicts.moving_average_window(free, {"w_ma_3": (0.9, 21), "w_ma_5": (0.6, 21)},
                                                                     "w_ma_5")), H)
        self.assertEqual(self.verdict(verdicts.moving_average_window(free, {"w_ma_3": (0.6, 21), "w_ma_5": (0.6, 21)},
                                                                     "w_ma_5")), P)
        same = {"w_ma_3": (0.2, 21), "w_ma_5": (0.2, 21)}
        # fewer walls is harm too
        self.assertEqual(self.verdict(verdicts.moving_average_window(same, {"w_ma_3": (0.5, 12), "w_ma_5": (0.6, 21)},
                                                                     "w_ma_5")), P)
        self.assertEqual(self.verdict(verdicts.moving_average_window(same, same, "w_ma_5")), N)

    def test_noise_sweep(self):
        self.assertEqual(self.verdict(verdicts.noise_sweep(1.0, 4.0, 0.9, 0.95)), H)
        self.assertEqual(self.verdict(verdicts.noise_sweep(1.0, 4.0, 0.96, 0.95)), P)
        self.assertEqual(self.verdict(verdicts.noise_sweep(1.0, 1.1, 0.96, 0.95)), N)

    def test_key_point_pair_and_interval_mode(self):
        self.assertEqual(self.verdict(verdicts.key_point_pair(0.03, [0.35, 0.86, 0.5], [1.0, 1.0])), H)
        self.assertEqual(self.verdict(verdicts.key_point_pair(0.03, [0.05, 0.86, 0.5], [1.0, 1.0])), P)
        self.assertEqual(self.verdict(verdicts.interval_mode(0.010, 0.020, 0.05, 0.05)), H)
        self.assertEqual(self.verdict(verdicts.interval_mode(0.010, 0.020, 0.05, 0.08)), P)
        # no contrast under random noise: nothing for the three-valued noise to remove
        self.assertEqual(self.verdict(verdicts.interval_mode(0.0152, 0.0124, 0.0685, 0.0689)), N)

    def test_healing_full_size_and_rule22(self):
        self.assertEqual(self.verdict(verdicts.wrong_key_points_heal(3, 0, 4)), H)
        self.assertEqual(self.verdict(verdicts.wrong_key_points_heal(9, 0, 4)), P)
        self.assertEqual(self.verdict(verdicts.wrong_key_points_heal(9, 2, 4)), N)
        self.assertEqual(self.verdict(verdicts.rule21_full_size(1, [0, 0])), H)
        self.assertEqual(self.verdict(verdicts.rule21_full_size(0, [0, 1])), N)
        self.assertEqual(self.verdict(verdicts.rule22_saving(94.1, 100.0)), H)   # 5.9 %
        self.assertEqual(self.verdict(verdicts.rule22_saving(99.0, 100.0)), P)   # 1 %: saves, not about 5 %
        self.assertEqual(self.verdict(verdicts.rule22_saving(101.0, 100.0)), N)
        self.assertEqual(self.verdict(verdicts.rule22_saving(1.0, 0.0)), N)

    def test_rules_28_19_37_and_the_save_system(self):
        self.assertEqual(self.verdict(verdicts.rule28(0, 5)), H)
        self.assertEqual(self.verdict(verdicts.rule28(1, 5)), P)
        self.assertEqual(self.verdict(verdicts.map_e_loop_closure((1, 1.09), (3, 1.13), (0, 7.8))), H)
        self.assertEqual(self.verdict(verdicts.map_e_loop_closure((1, 1.09), (1, 1.10), (0, 7.8))), P)
        walls = {"save_off": (31, 36), "save_on": (36, 36), "rule35_only": (36, 36)}
        self.assertEqual(self.verdict(verdicts.save_system(walls)), H)
        self.assertEqual(self.verdict(verdicts.save_system({**walls, "rule35_only": (30, 36)})), P)
        self.assertEqual(self.verdict(verdicts.pseudo_merge([448, 290], [0.05, 0.06], [0.5, 0.06], 0.1)), H)
        self.assertEqual(self.verdict(verdicts.pseudo_merge([448, 290], [0.05, 0.06], [0.05, 0.06], 0.1)), P)
        # a plane 1 not mapped at all is mis-mapped
        self.assertEqual(self.verdict(verdicts.pseudo_merge([0], [0.05], [float("nan")], 0.1)), P)
        self.assertEqual(self.verdict(verdicts.collinear(5, 36, 36, 0.06, 0.1)), H)
        self.assertEqual(self.verdict(verdicts.collinear(0, 30, 36, 0.06, 0.1)), N)

    def test_flat_time_first_corner_growth_frustum(self):
        self.assertEqual(self.verdict(verdicts.flat_time((0.146, 0.0847), (0.167, 0.1))), H)
        self.assertEqual(self.verdict(verdicts.flat_time((0.146, 0.0847), (0.167, 0.242))), P)
        self.assertEqual(self.verdict(verdicts.first_corner([1.5, 1.6], [1.006], 3, 2, 4)), H)
        self.assertEqual(self.verdict(verdicts.first_corner([1.5, 1.6], [1.006], 0, 0, 4)), P)
        self.assertEqual(self.verdict(verdicts.grown_past([1.0, 1.008, 1.01])), H)
        self.assertEqual(self.verdict(verdicts.grown_past([1.0, 1.2])), P)
        self.assertEqual(self.verdict(verdicts.grown_past([0.99, 1.0])), P)
        self.assertEqual(self.verdict(verdicts.frustum(7.15, 2.69, 9.79, 15.1, 15.0)), H)
        self.assertEqual(self.verdict(verdicts.frustum(7.15, 7.0, 7.2, 12.0, 15.0)), N)

    def test_plane_map_errors_skip_the_deliberate_duplicate(self):
        planes_csv = pd.DataFrame({"true_wall": [0, 0, 1], "e_ends": [7.5, 0.1, 0.3], "e_ang_deg": [0.0, -0.5, 0.2],
                                   "e_perp": [0.0, 0.02, -0.05], "n_obs": [150, 600, 400]})
        off, angle, ends = planes.plane_map_errors(planes_csv)
        self.assertEqual((off, angle), (0.05, 0.5))
        self.assertAlmostEqual(ends, 0.2)  # walls 0 (its 600-observation plane) and 1
        self.assertEqual(self.verdict(verdicts.plane_map(21, 21, 0.99, (0.0, 0.0, 0.05))), H)
        self.assertEqual(self.verdict(verdicts.plane_map(21, 21, 0.99, (0.0, 0.0, 0.197))), P)
        self.assertEqual(self.verdict(verdicts.plane_map(12, 21, 0.54, (0.27, 3.2, 0.57))), N)
        self.assertEqual(self.verdict(verdicts.plane_map(21, 21, 0.5, (0.0, 0.0, 0.05))), P)  # pose mostly lost

    def test_rule29_interval_checks_one_partial_plane(self):
        self.assertEqual(self.verdict(verdicts.rule29(6, 0, 16, 17)), H)
        self.assertEqual(self.verdict(verdicts.rule29(6, 1, 17, 17)), P)
        self.assertEqual(self.verdict(verdicts.interval_checks((8, 10, 1.0, 0), (10, 10, 1.0, 2))), H)
        self.assertEqual(self.verdict(verdicts.interval_checks((10, 10, 1.09, 0), (10, 10, 1.08, 2))), P)
        self.assertEqual(self.verdict(verdicts.one_partial_plane(259, 251)), H)
        self.assertEqual(self.verdict(verdicts.one_partial_plane(100, 60)), P)
        self.assertEqual(self.verdict(verdicts.one_partial_plane(0, 0)), N)


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1], verbosity=1)
