#pragma once
// One algorithm of the Relative Plane half (plane frames in, planar pose and a map of planes
// out) as the harness drives it; the counterpart of algorithm.hpp for the point half. The
// adapter only steps its algorithm and exposes what it estimates and its own diagnostics as
// named columns; scoring, files and status belong to the recorder
// (experiments/plane_recorder.hpp).

#include "relslam/core/planar_pose.hpp"
#include "relslam/core/plane_object.hpp"
#include "relslam/eval/io/csv_writer.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace relslam::eval {

// An estimated plane on the map: its id (what assignment() names) and where it is, world frame.
using MappedPlane = std::pair<int, PlaneObject>;

// A group of planes as the algorithm keeps it (thesis RltXPoint, 4.4.3.2): where the map placed
// its origin and which planes (ids of map()) belong to it. Read by pictures only
// (thesis Fig. 67: each group's label joined to its planes).
struct PlaneGroup {
  int id = 0;
  PlanarPose world_pose;
  std::vector<int> planes;
};

// What an algorithm says about which ends of an observed plane are real wall ends (thesis Rule
// 14's key point; key-point correctness), scored against the truth in keypoints.csv.
struct KeyPointClaim {
  int observation = 0;  // index in this iteration's frame
  int group = -1;       // where the claim comes from (-1: none)
  int plane = -1;       // the estimated plane (assignment())
  int key_point = 1;       // 1: the left end (a) is real, 2: the right end (b)
  bool is_static = false;  // the plane also kept its size in that comparison
  bool ambiguous = false;  // a comparison of it tied both diagonals (Rule 15)
  int interval_start = 0;  // the comparison piece the claim is valid in
  int interval_end = 0;
};

// A valid pose further than this from the truth is wrong-but-valid, units [C: the thesis's
// noisy runs stay within 0.25 of the truth (Maps D, E); the wrong poses it is meant to catch
// are a wall piece off, 1 and more].
inline constexpr double kWrongValidBound = 0.5;

class PlaneAlgorithm {
 public:
  virtual ~PlaneAlgorithm() = default;
  virtual const std::string& name() const = 0;

  // The timed work: one step on this frame (planes in the robot frame). Throws when it fails,
  // which ends its run.
  virtual void step(const PlaneFrame& frame) = 0;
  // Untimed, after step(): copy out whatever the accessors below report.
  virtual void read_out() {}

  // After step(): world_T_robot, or nothing when no pose could be computed this iteration.
  virtual std::optional<PlanarPose> pose() const = 0;
  // The estimated plane each observation went to, in input order (-1 none).
  virtual const std::vector<int>& assignment() const = 0;
  // The planes on the map now, ascending ids.
  virtual const std::vector<MappedPlane>& map() const = 0;
  // The groups placed on the map now; none for an algorithm that keeps no groups.
  virtual std::vector<PlaneGroup> groups() const { return {}; }

  // Its own columns of iterations.csv (after the shared score columns) and this step's fields.
  virtual std::vector<std::string> iteration_columns() const = 0;
  virtual void iteration_fields(std::vector<CsvField>& out) const = 0;
  // planes.csv: its columns after the scored ones, and the fields of estimated plane `id`.
  virtual std::vector<std::string> plane_columns() const = 0;
  virtual void plane_fields(int id, std::vector<CsvField>& out) const = 0;
  // Whether it makes key-point claims at all (then the run has a keypoints.csv), and after
  // read_out() this iteration's claims about the observed planes.
  virtual bool claims_key_points() const { return false; }
  virtual std::vector<KeyPointClaim> key_point_claims() const { return {}; }
  // At the end of the run: any tables of its own structure (groups.csv, links.csv) into dir.
  virtual void write_tables(const std::filesystem::path&) const {}
  // Whether the recorder counts its wrong-but-valid poses (iterations.csv's wrong_valid, a
  // summary.csv count): valid iterations whose position error exceeds kWrongValidBound.
  virtual bool scores_wrong_valid() const { return false; }
  // At the end of the run: its own summary.csv columns (after the scored ones) and their fields.
  virtual std::vector<std::string> summary_columns() const { return {}; }
  virtual void summary_fields(std::vector<CsvField>&) const {}
};

}  // namespace relslam::eval
