"""scripts/plot_run.py and scripts/plot_sweep.py on the tiny folders: the PNGs they promise, and
exit status 2 with the damaged file's name."""
import contextlib
import importlib.util
import io
import tempfile
import unittest
from pathlib import Path

import fixtures

PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


def script(name):
    """The script as a module, so its functions run in this process (faster than a subprocess)."""
    spec = importlib.util.spec_from_file_location(name, fixtures.REPOSITORY / "scripts" / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def call(main, argv):
    """main(argv)'s exit status and stderr."""
    err = io.StringIO()
    with contextlib.redirect_stderr(err), contextlib.redirect_stdout(io.StringIO()):
        status = main(argv)
    return status, err.getvalue()


class PlotScriptsTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.plot_run = script("plot_run")
        cls.plot_sweep = script("plot_sweep")

    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        self.folder = Path(self.dir.name)

    def tearDown(self):
        self.dir.cleanup()

    def assertPngs(self, paths, names):
        self.assertEqual(sorted(p.name for p in paths), sorted(f"{n}.png" for n in names))
        for path in paths:
            self.assertEqual(path.read_bytes()[:8], PNG_SIGNATURE)
            self.assertGreater(path.stat().st_size, 5000)

    def test_point_run(self):
        run = fixtures.point_run(self.folder / "run")
        paths = self.plot_run.plot_run(run, self.folder / "out")
        self.assertPngs(paths, ["errors", "runtime", "map_size", "top_view"])

    def test_planar_run(self):
        run = fixtures.planar_run(self.folder / "planar")
        paths = self.plot_run.plot_run(run, self.folder / "out")
        self.assertPngs(paths, ["errors", "runtime", "map_size", "top_view"])

    def test_run_without_truth_has_no_error_figure(self):
        """A data-set run (Victoria Park) has empty error columns and no truth files."""
        run = fixtures.point_run(self.folder / "run")
        for name in ("ground_truth_path.tum", "ground_truth_landmarks.csv"):
            (run / name).unlink()
        for algorithm in ("relative_point", "ekf6d"):
            fixtures.write(run, {f"{algorithm}/iterations.csv": "iteration,landmark_error,runtime_ms,landmarks_in_map\n"
                                                               "0,,0.1,1\n1,,0.2,2\n"})
        paths = self.plot_run.plot_run(run, self.folder / "out")
        self.assertPngs(paths, ["runtime", "map_size", "top_view"])

    def test_sweep_with_ratios(self):
        sweep = fixtures.sweep(self.folder / "sweep")
        paths = self.plot_sweep.plot_sweep(sweep, self.folder / "out", ratios=True)
        self.assertPngs(paths, ["final_mean_landmark_error", "final_mean_landmark_error_ratio"])

    def test_damaged_run_exits_2_naming_the_file(self):
        run = fixtures.point_run(self.folder / "run")
        (run / "ekf6d" / "iterations.csv").write_text("iteration,runtime_ms\n0,1\n1")
        status, err = call(self.plot_run.main, [str(run), "--out", str(self.folder / "out")])
        self.assertEqual(status, 2)
        self.assertIn("ekf6d/iterations.csv: cut short", err)

    def test_damaged_sweep_exits_2_naming_the_file(self):
        sweep = fixtures.sweep(self.folder / "sweep")
        (sweep / "aggregate.csv").unlink()
        status, err = call(self.plot_sweep.main, [str(sweep), "--out", str(self.folder / "out")])
        self.assertEqual(status, 2)
        self.assertIn("aggregate.csv: file not found", err)

    def test_unknown_metric_is_a_usage_error(self):
        sweep = fixtures.sweep(self.folder / "sweep")
        with self.assertRaises(SystemExit) as caught:
            call(self.plot_sweep.main, [str(sweep), "--metric", "nothing"])
        self.assertEqual(caught.exception.code, 2)


if __name__ == "__main__":
    unittest.main()
