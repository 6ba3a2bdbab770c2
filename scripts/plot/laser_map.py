"""The wall map of a laser run over ICP-SLAM's point map: a recorded log has no true walls, so the
walls Relative Plane put on its map (planes.csv's key points) are drawn over the points MRPT's
ICP-SLAM mapped from the same scans (icp_slam/icp_points.csv), with every algorithm's path.
Reads the run folder's CSV files only (docs/laser-scans.md)."""
import matplotlib.pyplot as plt

POINT_COLOUR = "0.55"
MAX_POINTS = 40000  # ICP-SLAM's map is thinned to this many points for drawing


def has_point_map(run):
    """True for a run with ICP-SLAM's point map (a laser run with the icp_slam algorithm)."""
    return (run.folder / "icp_slam" / "icp_points.csv").is_file()


def plot_wall_map(run, colour, label):
    """ICP-SLAM's points grey, each algorithm's mapped walls as segments and its path in its colour;
    None without a point map. `colour` maps algorithm names to colours, `label` names to legend text."""
    import pandas as pd

    if not has_point_map(run):
        return None
    points = pd.read_csv(run.folder / "icp_slam" / "icp_points.csv")
    step = max(1, len(points) // MAX_POINTS)
    fig, ax = plt.subplots(figsize=(10, 8))
    ax.scatter(points["x"][::step], points["z"][::step], s=0.5, c=POINT_COLOUR, lw=0,
               label=f"{label('icp_slam')} point map")
    for name, algorithm in run.algorithms.items():
        planes = algorithm.planes
        if planes is not None and len(planes) and {"kp1_x", "kp2_x"} <= set(planes.columns):
            walls = planes.dropna(subset=["kp1_x", "kp1_z", "kp2_x", "kp2_z"])
            for i, w in enumerate(walls.itertuples(index=False)):
                ax.plot([w.kp1_x, w.kp2_x], [w.kp1_z, w.kp2_z], color=colour[name], lw=2.2, alpha=0.85,
                        label=f"{label(name)} walls ({len(walls)})" if i == 0 else None)
        if algorithm.trajectory is not None and len(algorithm.trajectory):
            ax.plot(algorithm.trajectory["x"], algorithm.trajectory["z"], lw=0.8, ls=":", color=colour[name],
                    label=f"{label(name)} path")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("z (m)")
    ax.set_aspect("equal", adjustable="datalim")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1))  # beside the map, never over it
    ax.set_title(f"{run.name}: walls over {label('icp_slam')}'s point map")
    return fig
