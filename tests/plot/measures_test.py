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

from measures import common, compare, em, planes, points  # noqa: E402
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


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1], verbosity=1)
