"""load_sweep on a tiny two-axis sweep, whole and damaged, and the metric-against-axis tables."""
import tempfile
import unittest
from pathlib import Path

import fixtures
from relslam_data import DataError, load_sweep
from relslam_data import frames


class LoadSweepTest(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        self.folder = fixtures.sweep(Path(self.dir.name) / "sweep")

    def tearDown(self):
        self.dir.cleanup()

    def test_sweep(self):
        sweep = load_sweep(self.folder)
        self.assertEqual(sweep.name, "tiny-sweep")
        self.assertEqual(sweep.axes, ["sim.noise_sigma", "variant"])
        self.assertEqual(sweep.metrics, ["final_mean_landmark_error"])
        self.assertEqual(len(sweep.runs), 8)
        self.assertEqual(len(sweep.aggregate), 12)
        self.assertEqual(sweep.plan["axes"][1]["name"], "variant")

    def test_cell_run(self):
        sweep = load_sweep(self.folder)
        run = sweep.run(sweep.runs.iloc[0])
        self.assertEqual(run.folder, self.folder / "sim.noise_sigma=0.1/variant=wide/seed-1")
        self.assertEqual(list(run.algorithms), ["relative_point", "ekf6d"])
        self.assertEqual(sweep.run("sim.noise_sigma=0.05/variant=narrow/seed-2").name, "tiny-f8")

    def test_without_plan(self):
        (self.folder / "plan.json").unlink()
        self.assertIsNone(load_sweep(self.folder).plan)

    def assertDamaged(self, relative, problem):
        with self.assertRaises(DataError) as caught:
            load_sweep(self.folder)
        self.assertEqual(caught.exception.path, self.folder / relative)
        self.assertIn(problem, str(caught.exception))

    def test_missing_aggregate(self):
        (self.folder / "aggregate.csv").unlink()
        self.assertDamaged("aggregate.csv", "file not found")

    def test_cut_sweep_csv(self):
        path = self.folder / "sweep.csv"
        path.write_text(path.read_text().rstrip("\n"))
        self.assertDamaged("sweep.csv", "cut short")

    def test_interval_not_a_number(self):
        path = self.folder / "aggregate.csv"
        lines = path.read_text().splitlines()
        lines[2] = lines[2].rsplit(",", 1)[0] + ",oops"
        path.write_text("\n".join(lines) + "\n")
        self.assertDamaged("aggregate.csv", "line 3: column final_mean_landmark_error_ci95: not a number: 'oops'")

    def test_axis_missing_from_sweep_csv(self):
        path = self.folder / "sweep.csv"
        path.write_text(path.read_text().replace("variant,seed", "variety,seed", 1))
        self.assertDamaged("aggregate.csv", "axis column(s) variant not in sweep.csv")

    def test_run_folder_is_named_as_such(self):
        fixtures.point_run(self.folder / "run")
        with self.assertRaises(DataError) as caught:
            load_sweep(self.folder / "run")
        self.assertIn("sweep.csv: file not found: this is a run folder", str(caught.exception))

    def test_invalid_plan(self):
        (self.folder / "plan.json").write_text("{\n")
        self.assertDamaged("plan.json", "not valid JSON")


class SweepFramesTest(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        self.sweep = load_sweep(fixtures.sweep(Path(self.dir.name) / "sweep"))

    def tearDown(self):
        self.dir.cleanup()

    def test_numeric_axis_in_value_order(self):
        self.assertTrue(frames.is_numeric_axis(["0.1", "0.05", "1e-3"]))
        self.assertEqual(frames.axis_order(self.sweep, "sim.noise_sigma"), ["0.05", "0.1"])

    def test_categorical_axis_in_plan_order(self):
        self.assertFalse(frames.is_numeric_axis(["wide", "0.1"]))
        self.assertEqual(frames.axis_order(self.sweep, "variant"), ["wide", "narrow"])

    def test_metric_against_numeric_axis(self):
        table = frames.metric_vs_axis(self.sweep, "final_mean_landmark_error", "sim.noise_sigma")
        self.assertEqual(list(table["algorithm"].unique()), ["relative_point", "ekf6d"])  # no ratio rows
        first = table[(table["algorithm"] == "ekf6d") & (table["series"] == "variant=wide")]
        self.assertEqual(list(first["x"]), [0.05, 0.1])
        self.assertEqual(list(first["mean"]), [0.1, 0.2])
        self.assertEqual(list(first["ci95"]), [0.02, 0.04])

    def test_metric_against_categorical_axis(self):
        table = frames.metric_vs_axis(self.sweep, "final_mean_landmark_error", "variant")
        line = table[(table["algorithm"] == "relative_point") & (table["series"] == "sim.noise_sigma=0.1")]
        self.assertEqual(list(line["label"]), ["wide", "narrow"])
        self.assertEqual(list(line["x"]), [0.0, 1.0])

    def test_ratio_rows_alone(self):
        table = frames.metric_vs_axis(self.sweep, "final_mean_landmark_error", "variant", ratios=True)
        self.assertEqual(set(table["algorithm"]), {"relative_point/ekf6d"})

    def test_dodge_spreads_lines_around_the_category(self):
        table = frames.metric_vs_axis(self.sweep, "final_mean_landmark_error", "variant")
        shifted = frames.dodge(table) - table["x"]
        self.assertAlmostEqual(shifted.mean(), 0.0)
        self.assertEqual(shifted.round(9).nunique(), 4)  # two algorithms x two noise levels


if __name__ == "__main__":
    unittest.main()
