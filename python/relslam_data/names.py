"""Readable names for figures: algorithm legends and metric axis labels with units.

The CSV columns are identifiers (relative_point, final_mean_landmark_error); a reader of a figure
wants "Relative Point" and "final landmark error per landmark (units)". Distances are in the
simulation's length unit, written "units" as in the thesis's figures.
"""

ALGORITHMS = {
    "relative_point": "Relative Point",
    "relative_plane": "Relative Plane",
    "ekf6d": "EKF (MRPT, 6D)",
    "ekf2d": "EKF (MRPT, 2D)",
    "ekf2d_no_odometry": "EKF (MRPT, 2D, no odometry)",
    "icp_slam": "ICP-SLAM (MRPT)",
    "odometry": "odometry",
    "wall_odometry": "wall registration (prediction)",
}

# metric -> (what it is, unit or None); a metric not listed gets its unit from its name's suffix.
METRICS = {
    "landmark_error": ("landmark error, sum over the map", "units"),
    "mean_landmark_error": ("landmark error per landmark", "units"),
    "final_landmark_error": ("final landmark error, sum over the map", "units"),
    "final_mean_landmark_error": ("final landmark error per landmark", "units"),
    "map_error": ("map error, sum over the planes", "units"),
    "mean_map_error": ("map error per plane", "units"),
    "final_map_error": ("final map error, sum over the planes", "units"),
    "final_mean_map_error": ("final map error per plane", "units"),
    "position_error": ("position error", "units"),
    "final_position_error": ("final position error", "units"),
    "max_position_error": ("largest position error", "units"),
    "heading_error_deg": ("heading error", "°"),
    "final_heading_error_deg": ("final heading error", "°"),
    "ate_rmse": ("ATE RMSE", "units"),
    "ate_rmse_aligned": ("ATE RMSE after alignment", "units"),
    "rpe_translation_rmse": ("RPE translation RMSE", "units"),
    "rpe_rotation_rmse_deg": ("RPE rotation RMSE", "°"),
    "runtime_ms": ("run time per iteration", "ms"),
    "runtime_median_ms": ("median run time per iteration", "ms"),
    "runtime_mean_ms": ("mean run time per iteration", "ms"),
    "runtime_p95_ms": ("95th percentile run time per iteration", "ms"),
    "runtime_max_ms": ("longest iteration", "ms"),
    "landmarks_in_map": ("landmarks on the map", "count"),
    "landmarks_on_map": ("landmarks on the map", "count"),
    "planes_in_map": ("planes on the map", "count"),
    "planes_on_map": ("planes on the map", "count"),
    "peak_rss_mb": ("peak memory (RSS)", "MB"),
    "pose_valid_fraction": ("share of iterations with a pose", None),
}

SUFFIX_UNITS = {"_ms": "ms", "_deg": "°", "_mb": "MB", "_error": "units", "_rmse": "units"}

# Swept keys whose values have a unit (the others are counts, names or switches).
AXIS_UNITS = {"sim.noise_sigma": "units"}


def algorithm_label(name):
    """Legend name of an algorithm; a ratio row 'a/b' reads 'A / B'; unknown names are title-cased."""
    if "/" in name:
        return " / ".join(algorithm_label(part) for part in name.split("/"))
    return ALGORITHMS.get(name, name.replace("_", " ").title())


def metric_label(name):
    """Axis label of a metric column, with its unit in parentheses where it has one."""
    description, unit = METRICS.get(name, (name.replace("_", " "), _suffix_unit(name)))
    return f"{description} ({unit})" if unit else description


def _suffix_unit(name):
    """A metric's unit by its name's ending, so new columns get a sensible label without an entry."""
    return next((unit for suffix, unit in SUFFIX_UNITS.items() if name.endswith(suffix)), None)


def axis_label(name):
    """Axis label of a swept key: the key as typed after --param, with its unit where known."""
    unit = AXIS_UNITS.get(name)
    return f"{name} ({unit})" if unit else name
