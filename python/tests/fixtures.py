"""Tiny run and sweep folders for the tests, written in the layout relslam writes (a few rows each),
so the loaders are tested without the binary. test_real_folders.py checks the real thing."""
import json
import sys
from pathlib import Path

# The package under test is the one beside these tests (python/), installed or not.
PACKAGE_ROOT = Path(__file__).resolve().parents[1]
REPOSITORY = PACKAGE_ROOT.parent
sys.path.insert(0, str(PACKAGE_ROOT))

POINT_SUMMARY = """algorithm,status,iterations,final_mean_landmark_error,runtime_median_ms
relative_point,ok,3,0.1,0.01
ekf6d,ok,3,0.2,1.5
relative_point/ekf6d,ratio,3,0.5,0.0067
"""
RP_ITERATIONS = """iteration,landmark_error,mean_landmark_error,position_error,runtime_ms,landmarks_in_map,pose_source
0,0,0,0,0.04,0,start
1,0.3,0.1,0.05,0.02,3,unmapped
2,0.6,0.2,0.07,0.03,3,relative
"""
EKF_ITERATIONS = """iteration,landmark_error,mean_landmark_error,position_error,runtime_ms,landmarks_in_map
0,0.5,0.25,0,1.2,2
1,0.6,0.2,0.06,1.5,3
2,0.6,0.2,0.08,1.6,3
"""
LANDMARKS = """id,x,y,z,true_id,error,level
0,1.0,0.5,2.0,0,0.1,final
1,,,,1,,none
2,-1.0,0.4,3.0,2,0.2,final
"""
TRAJECTORY = "0 0 0 0 0 0 0 1\n1 0.1 0 0.3 0 0 0 1\n2 0.2 0 0.6 0 0 0 1\n"
TRUTH_LANDMARKS = "id,x,y,z,dynamic\n0,1,0.5,2,0\n1,0,0,5,0\n2,-1,0.5,3,1\n"
PLANAR_SUMMARY = "algorithm,status,iterations,final_mean_map_error,runtime_median_ms\nrelative_plane,ok,2,0.3,0.05\n"
PLANAR_ITERATIONS = """iteration,map_error,mean_map_error,position_error,heading_error_deg,runtime_ms,planes_in_map
0,0,,,,0.02,0
1,0.6,0.3,0.02,0.1,0.01,2
"""
PLANES = "id,true_wall,kp1_x,kp1_z,kp2_x,kp2_z\n0,0,0,0,4,0\n1,1,4,0.1,4,3\n"
WALLS = "id,a_x,a_z,b_x,b_z,length\n0,0,0,4,0,4\n1,4,0,4,3,3\n"


def write(folder, files):
    """Writes {relative path: text} below folder (dicts become JSON); returns the folder."""
    folder = Path(folder)
    for name, content in files.items():
        path = folder / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(json.dumps(content) + "\n" if isinstance(content, dict) else content)
    return folder


def point_run(folder, name="tiny-f8"):
    """A simulated run of relative_point and ekf6d with its truth and the ratio row."""
    files = {"manifest.json": {"command": "run", "scenario": {"name": name}}, "summary.csv": POINT_SUMMARY,
             "ground_truth_path.tum": TRAJECTORY, "ground_truth_landmarks.csv": TRUTH_LANDMARKS,
             "sim_iterations.csv": "iteration,x,y,z\n0,0,0,0\n"}
    for algorithm, iterations in (("relative_point", RP_ITERATIONS), ("ekf6d", EKF_ITERATIONS)):
        files.update({f"{algorithm}/iterations.csv": iterations, f"{algorithm}/landmarks.csv": LANDMARKS,
                      f"{algorithm}/trajectory.tum": TRAJECTORY})
    return write(folder, files)


def planar_run(folder):
    """A planar run of relative_plane: planes.csv instead of landmarks.csv, walls as truth."""
    return write(folder, {"manifest.json": {"command": "run", "scenario": {"name": "tiny-room"}},
                          "summary.csv": PLANAR_SUMMARY, "ground_truth_path.tum": TRAJECTORY,
                          "ground_truth_walls.csv": WALLS, "relative_plane/iterations.csv": PLANAR_ITERATIONS,
                          "relative_plane/planes.csv": PLANES, "relative_plane/trajectory.tum": TRAJECTORY})


def sweep(folder):
    """A two-axis sweep (numeric sim.noise_sigma, categorical variant listed 'wide' before 'narrow'
    in the plan) of relative_point and ekf6d over two seeds, with run folders for its cells."""
    folder = Path(folder)
    runs = ["sim.noise_sigma,variant,seed,folder,algorithm,status,final_mean_landmark_error"]
    aggregate = ["sim.noise_sigma,variant,algorithm,runs,ok,not_ok_seeds,"
                 "final_mean_landmark_error_mean,final_mean_landmark_error_std,final_mean_landmark_error_ci95"]
    for sigma in ("0.1", "0.05"):  # deliberately not sorted: the loader must order numeric axes itself
        for variant in ("wide", "narrow"):
            cell = f"sim.noise_sigma={sigma}/variant={variant}"
            for seed in (1, 2):
                runs.append(f"{sigma},{variant},{seed},{cell}/seed-{seed},relative_point,ok,{float(sigma) * seed}")
                point_run(folder / cell / f"seed-{seed}")
            for algorithm, scale in (("relative_point", 1), ("ekf6d", 2), ("relative_point/ekf6d", 0.5)):
                mean = float(sigma) * scale
                aggregate.append(f"{sigma},{variant},{algorithm},2,2,,{mean},{mean / 10},{mean / 5}")
    plan = {"axes": [{"name": "sim.noise_sigma", "values": [{"label": "0.1"}, {"label": "0.05"}]},
                     {"name": "variant", "values": [{"label": "wide"}, {"label": "narrow"}]}]}
    return write(folder, {"manifest.json": {"command": "sweep", "scenario": {"name": "tiny-sweep"}},
                          "plan.json": plan, "sweep.csv": "\n".join(runs) + "\n",
                          "aggregate.csv": "\n".join(aggregate) + "\n"})
