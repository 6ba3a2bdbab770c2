"""load_run on tiny point and planar run folders, whole and damaged, and the frames drawn from them."""
import shutil
import tempfile
import unittest
from pathlib import Path

import fixtures
from relslam_data import DataError, load_run
from relslam_data import frames


class LoadRunTest(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        self.run = fixtures.point_run(Path(self.dir.name) / "run")

    def tearDown(self):
        self.dir.cleanup()

    def test_point_run(self):
        run = load_run(self.run)
        self.assertEqual(run.name, "tiny-f8")
        self.assertEqual(list(run.algorithms), ["relative_point", "ekf6d"])  # not the ratio row
        self.assertEqual(list(run.ratios["algorithm"]), ["relative_point/ekf6d"])
        rp = run.algorithms["relative_point"]
        self.assertEqual(list(rp.iterations["pose_source"]), ["start", "unmapped", "relative"])
        self.assertEqual(len(rp.landmarks), 3)
        self.assertEqual(len(rp.trajectory), 3)
        self.assertIsNone(rp.planes)
        self.assertEqual(len(run.truth_landmarks), 3)
        self.assertEqual(len(run.truth_path), 3)
        self.assertIsNone(run.truth_walls)
        self.assertEqual(len(run.table("sim_iterations.csv")), 1)

    def test_planar_run(self):
        run = load_run(fixtures.planar_run(Path(self.dir.name) / "planar"))
        plane = run.algorithms["relative_plane"]
        self.assertEqual(len(plane.planes), 2)
        self.assertIsNone(plane.landmarks)
        self.assertEqual(len(run.truth_walls), 2)
        self.assertTrue(run.ratios.empty)

    def test_name_falls_back_to_the_folder(self):
        fixtures.write(self.run, {"manifest.json": {"command": "run"}})
        self.assertEqual(load_run(self.run).name, "run")

    def assertDamaged(self, relative, problem):
        with self.assertRaises(DataError) as caught:
            load_run(self.run)
        self.assertEqual(caught.exception.path, self.run / relative)
        self.assertIn(problem, str(caught.exception))

    def test_not_a_folder(self):
        shutil.rmtree(self.run)
        self.assertDamaged("", "not a folder")

    def test_missing_summary(self):
        (self.run / "summary.csv").unlink()
        self.assertDamaged("summary.csv", "file not found")

    def test_sweep_folder_is_named_as_such(self):
        (self.run / "summary.csv").unlink()
        fixtures.write(self.run, {"sweep.csv": "seed,folder,algorithm,status\n"})
        self.assertDamaged("summary.csv", "this is a sweep folder")

    def test_missing_manifest(self):
        (self.run / "manifest.json").unlink()
        self.assertDamaged("manifest.json", "file not found")

    def test_finished_algorithm_without_iterations(self):
        (self.run / "ekf6d" / "iterations.csv").unlink()
        self.assertDamaged("ekf6d/iterations.csv", "file not found")

    def test_cut_iterations(self):
        path = self.run / "relative_point" / "iterations.csv"
        path.write_text(path.read_text()[:-5])
        self.assertDamaged("relative_point/iterations.csv", "cut short")

    def test_cut_truth(self):
        path = self.run / "ground_truth_path.tum"
        path.write_text(path.read_text()[:-3])
        self.assertDamaged("ground_truth_path.tum", "cut short")

    def test_failed_algorithm_without_folder_is_left_out(self):
        summary = fixtures.POINT_SUMMARY.replace("ekf6d,ok", "ekf6d,error: diverged")
        fixtures.write(self.run, {"summary.csv": summary})
        shutil.rmtree(self.run / "ekf6d")
        self.assertEqual(list(load_run(self.run).algorithms), ["relative_point"])


class RunFramesTest(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        self.run = load_run(fixtures.point_run(Path(self.dir.name) / "run"))

    def tearDown(self):
        self.dir.cleanup()

    def test_iterations_long(self):
        long = frames.iterations_long(self.run)
        self.assertEqual(len(long), 6)
        self.assertEqual(list(long["algorithm"].unique()), ["relative_point", "ekf6d"])

    def test_present_columns_skip_absent_and_empty(self):
        long = frames.iterations_long(self.run).assign(map_error=float("nan"))
        self.assertEqual(frames.present_columns(long, frames.ERROR_COLUMNS),
                         ["mean_landmark_error", "landmark_error", "position_error"])

    def test_moving_average(self):
        self.assertEqual(list(frames.moving_average([3, 6, 9, 12], 3)), [3, 4.5, 6, 9])

    def test_top_view(self):
        view = frames.top_view(self.run)
        self.assertEqual([name for name, _ in view.paths], ["truth", "relative_point", "ekf6d"])
        self.assertEqual(len(view.maps["ekf6d"]), 2)  # the landmark without a position is left out
        self.assertEqual(list(view.truth_points.columns), ["x", "z"])

    def test_top_view_of_planes_shows_both_ends(self):
        view = frames.top_view(load_run(fixtures.planar_run(Path(self.dir.name) / "planar")))
        self.assertEqual(len(view.maps["relative_plane"]), 4)
        self.assertEqual(len(view.walls), 2)


if __name__ == "__main__":
    unittest.main()
