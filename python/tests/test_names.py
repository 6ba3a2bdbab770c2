"""Legend and axis names: readable, with units, and never failing on a name they do not know."""
import unittest

import fixtures  # noqa: F401  (puts the package beside the tests on the path)
from relslam_data.names import algorithm_label, axis_label, metric_label


class NamesTest(unittest.TestCase):
    def test_algorithms(self):
        self.assertEqual(algorithm_label("relative_point"), "Relative Point")
        self.assertEqual(algorithm_label("ekf6d"), "EKF (MRPT, 6D)")
        self.assertEqual(algorithm_label("relative_point/ekf6d"), "Relative Point / EKF (MRPT, 6D)")
        self.assertEqual(algorithm_label("new_method"), "New Method")

    def test_metrics_carry_units(self):
        self.assertEqual(metric_label("runtime_median_ms"), "median run time per iteration (ms)")
        self.assertEqual(metric_label("final_mean_landmark_error"), "final landmark error per landmark (units)")
        self.assertEqual(metric_label("rpe_rotation_rmse_deg"), "RPE rotation RMSE (°)")
        self.assertEqual(metric_label("t_binning_ms"), "t binning ms (ms)")
        self.assertEqual(metric_label("walls_mapped"), "walls mapped")

    def test_axes(self):
        self.assertEqual(axis_label("sim.noise_sigma"), "sim.noise_sigma (units)")
        self.assertEqual(axis_label("variant"), "variant")


if __name__ == "__main__":
    unittest.main()
