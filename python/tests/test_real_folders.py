"""The loaders on folders the relslam binary writes: a point run with the EKF and the truth, a
planar run and a sweep. Skipped unless RELSLAM_BINARY names the binary (ctest's Plot.PythonPackage
sets it), e.g. RELSLAM_BINARY=build/relslam python3 -m unittest discover -s python/tests"""
import os
import subprocess
import tempfile
import unittest
from pathlib import Path

import fixtures
from relslam_data import load_run, load_sweep
from relslam_data import frames

BINARY = os.environ.get("RELSLAM_BINARY")


def relslam(*arguments):
    """Runs the binary from the repository root (scenario paths are relative to it); quiet."""
    subprocess.run([BINARY, *arguments, "-q"], cwd=fixtures.REPOSITORY, check=True, stdout=subprocess.DEVNULL)


@unittest.skipUnless(BINARY, "set RELSLAM_BINARY to the relslam binary to load folders it writes")
class RealFoldersTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.dir = tempfile.TemporaryDirectory()
        cls.folder = Path(cls.dir.name)
        relslam("run", "scenarios/s-ekf-f8.json", "--out", str(cls.folder / "run"), "--set", "sim.iterations=40")
        relslam("run", "scenarios/p-room.json", "--out", str(cls.folder / "planar"), "--set", "planar.iterations=100")
        relslam("sweep", "scenarios/s-f8.json", "--out", str(cls.folder / "sweep"), "--param",
                "sim.noise_sigma=0.05,0.1", "--seeds", "2", "--set", "sim.iterations=30", "--jobs", "1")

    @classmethod
    def tearDownClass(cls):
        cls.dir.cleanup()

    def test_point_run(self):
        run = load_run(self.folder / "run")
        self.assertEqual(list(run.algorithms), ["relative_point", "ekf6d"])
        self.assertEqual(list(run.ratios["algorithm"]), ["relative_point/ekf6d"])
        for algorithm in run.algorithms.values():
            self.assertEqual(len(algorithm.iterations), 40)
            self.assertIn("mean_landmark_error", algorithm.iterations.columns)
            self.assertGreater(len(algorithm.landmarks), 0)
            self.assertGreater(len(algorithm.trajectory), 0)
        self.assertGreater(len(run.truth_landmarks), 0)
        self.assertEqual(len(run.truth_path), 40)
        self.assertEqual(len(frames.iterations_long(run)), 80)

    def test_planar_run(self):
        run = load_run(self.folder / "planar")
        plane = run.algorithms["relative_plane"]
        self.assertIn("mean_map_error", plane.iterations.columns)
        self.assertGreater(len(plane.planes), 0)
        self.assertGreater(len(run.truth_walls), 0)
        self.assertGreater(len(plane.table("groups.csv")), 0)

    def test_sweep(self):
        sweep = load_sweep(self.folder / "sweep")
        self.assertEqual(sweep.axes, ["sim.noise_sigma"])
        self.assertIn("final_mean_landmark_error", sweep.metrics)
        self.assertIn("runtime_median_ms", sweep.metrics)
        self.assertEqual(len(sweep.runs), 4)
        table = frames.metric_vs_axis(sweep, "ate_rmse", "sim.noise_sigma")
        self.assertEqual(list(table["x"]), [0.05, 0.1])
        self.assertTrue(table["ci95"].notna().all())
        self.assertEqual(len(sweep.run(sweep.runs.iloc[-1]).algorithms["relative_point"].iterations), 30)


if __name__ == "__main__":
    unittest.main()
