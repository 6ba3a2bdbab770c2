#pragma once
// Everything one planar-world run is built from: the walls, the robot's path and the sensor the
// map was made for. Part of relslam/sim: no I/O; map files are read
// in eval/io (planar_map_file.hpp).

#include "relslam/sim/planar_path.hpp"
#include "relslam/sim/planar_world.hpp"
#include "relslam/sim/plane_sensor.hpp"

#include <string>

namespace relslam::sim {

struct PlanarMap {
  std::string name;         // e.g. "A FourPlanes"
  std::string description;  // purpose and the thesis figures it rebuilds
  PlanarWorld world;
  PathProgram path;
  // The sensor the map was designed for (a hint: a run may change any of it), e.g. Map A's
  // always-visible mode or Map B's scripted windows.
  PlaneSensorOptions sensor;
};

}  // namespace relslam::sim
