#!/usr/bin/python3
"""Unit checks of the fit and smoothing helpers of scripts/plot/measures/common.py: fits recover known
coefficients, the moving average matches its definition. Usage: fit_test.py <source dir>"""
import os
import sys

sys.path.insert(0, os.path.join(sys.argv[1], "scripts", "plot"))
import numpy as np  # noqa: E402

from measures import common as fg  # noqa: E402
import relslam_plot as rp  # noqa: E402

failures = []


def check(name, ok):
    print(f"{'ok' if ok else 'FAIL'}: {name}")
    if not ok:
        failures.append(name)


n = np.array([20.0, 50, 100, 200, 400])
check("n log n fit recovers c = 0.37", abs(fg.fit_scale(n, 0.37 * n * np.log(n), fg.n_log_n) - 0.37) < 1e-12)
check("n fit recovers c = 2.5", abs(fg.fit_scale(n, 2.5 * n, lambda x: x) - 2.5) < 1e-12)
noisy = 0.37 * n * np.log(n) * (1 + 0.01 * np.array([1, -1, 1, -1, 1]))
check("n log n fit is least squares under noise", abs(fg.fit_scale(n, noisy, fg.n_log_n) - 0.37) < 0.01)
slope, intercept = fg.line_fit(n, 3 * n - 7)
check("line fit recovers slope 3, intercept -7", abs(slope - 3) < 1e-9 and abs(intercept + 7) < 1e-7)
check("moving average of width 3", np.allclose(rp.moving_average([3, 6, 9, 12], 3), [3, 4.5, 6, 9]))
check("steady state skips 200 iterations of a long run", len(fg.steady(np.arange(1000))) == 800)
check("steady state keeps the second half of a short run", fg.steady(np.arange(100))[0] == 50)
sys.exit(1 if failures else 0)
