#include "relslam/eval/io/planar_map_file.hpp"

#include "relslam/eval/config/input_error.hpp"
#include "relslam/sim/planar_sight.hpp"
#include "relslam/sim/planar_simulator.hpp"
#include "refusal_limits.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace relslam::eval {
namespace {

// Robot positions along a path are fractions of a MOVE: a few ulps of coordinates of ~40.
constexpr double kPathTolerance = 1e-9;

std::filesystem::path map_file(const std::string& name) { return test::source_path("scenarios/maps/" + name); }

// A small valid map: two walls ahead of the robot, which the small frustum sees at once.
// Line 3 holds wall 0, line 4 wall 1, line 8 the steps.
std::string map_text(const std::string& wall0 = R"({"a": [5, -1], "b": [5, 1], "facing": "-x"})",
                     const std::string& wall1 = R"({"a": [6, 1], "b": [6, 2], "facing": "-x"})",
                     const std::string& steps = R"(["MOVE 1"])") {
  return "{\n"
         "  \"walls\": [\n"
         "    " +
         wall0 +
         ",\n"
         "    " +
         wall1 +
         "\n"
         "  ],\n"
         "  \"path\": {\n"
         "    \"start\": {\"x\": 0, \"z\": 0, \"heading_deg\": 0},\n"
         "    \"steps\": " +
         steps +
         "\n"
         "  }\n"
         "}\n";
}

std::string error_of(const std::string& text) {
  try {
    parse_planar_map(text, "m.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(PlanarMapFile, EveryShippedMapLoads) {
  const std::pair<const char*, std::size_t> maps[] = {{"a_four_planes.json", 4},   {"b_hallway_unit.json", 16},
                                                      {"c_hallway_back.json", 19}, {"d_office_loop.json", 36},
                                                      {"e_motion_room.json", 10},  {"e1_first_corner.json", 10},
                                                      {"e01_two_walls.json", 2},   {"d_office_loop_e09.json", 36},
                                                      {"i_room_30_120.json", 5},  {"i_corridor_l17.json", 18},
                                                      {"i_corridor_l17_mirrored.json", 19}, {"i_hexagon.json", 6}};
  std::size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(test::source_path("scenarios/maps")))
    files += entry.path().extension() == ".json";
  EXPECT_EQ(files, std::size(maps)) << "a new map file needs a line here";
  for (const auto& [name, walls] : maps) {
    const sim::PlanarMap map = read_planar_map(map_file(name));
    EXPECT_EQ(map.world.walls.size(), walls) << name;
    EXPECT_FALSE(map.description.empty()) << name;
    const sim::PlanarSimulator simulator(map, 1);
    EXPECT_GT(simulator.iterations(), 100) << name;
  }
}

TEST(PlanarMapFile, MapAWallsFaceIntoTheRoomInFileOrder) {
  const sim::PlanarMap map = read_planar_map(map_file("a_four_planes.json"));
  EXPECT_EQ(map.name, "A FourPlanes");
  EXPECT_EQ(map.sensor.mode, sim::PlaneVisibility::AlwaysVisible);
  EXPECT_EQ(map.path.loops, 10);
  EXPECT_EQ(map.path.start.translation, Eigen::Vector2d(-2, -2));
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(map.world.walls[i].id, static_cast<int>(i));
    EXPECT_TRUE(map.world.walls[i].faces({0, 0})) << "wall " << i;
    EXPECT_EQ(map.world.walls[i].length(), 8.0);
  }
  // Written a = (−4, 5), b = (4, 5) facing −z: the ends are swapped so the front faces −z.
  EXPECT_EQ(map.world.walls[2].a, Eigen::Vector2d(4, 5));
  EXPECT_EQ(map.world.walls[2].b, Eigen::Vector2d(-4, 5));
  EXPECT_EQ(map.world.walls[2].normal(), Eigen::Vector2d(0, -1));
}

TEST(PlanarMapFile, MapBWindowsFollowTheSpecsOverlapRule) {
  // a piece is visible iff its x-extent overlaps [x_r + 1, x_r + 8].
  const sim::PlanarMap map = read_planar_map(map_file("b_hallway_unit.json"));
  const sim::PlanarPath path(map.path);
  ASSERT_EQ(path.iterations(), 761);
  for (const sim::Wall& wall : map.world.walls) {
    const double x0 = std::min(wall.a.x(), wall.b.x()), x1 = std::max(wall.a.x(), wall.b.x());
    for (int k = 0; k < path.iterations(); ++k) {
      const double x_r = path.world_T_robot(k).translation.x();
      const bool overlaps = x0 <= x_r + 8 + kPathTolerance && x1 >= x_r + 1 - kPathTolerance;
      const bool scripted = std::any_of(wall.scripted_windows.begin(), wall.scripted_windows.end(),
                                        [k](const sim::IterationWindow& w) { return w.contains(k); });
      ASSERT_EQ(scripted, overlaps) << "wall " << wall.id << " k " << k;
    }
  }
}

TEST(PlanarMapFile, MapCTurnsAroundOnTheLineOfTheSideCorridorWall) {
  const sim::PlanarMap map = read_planar_map(map_file("c_hallway_back.json"));
  const sim::PlanarPath path(map.path);
  EXPECT_EQ(path.world_T_robot(path.operation_ends()[0]).translation, Eigen::Vector2d(36, 0));
  const sim::Wall& side = map.world.walls.back();
  EXPECT_EQ(side.a.x(), 36.0);
  EXPECT_EQ(side.b.x(), 36.0);
  EXPECT_EQ(side.normal(), Eigen::Vector2d(-1, 0));
  EXPECT_EQ(map.sensor.mode, sim::PlaneVisibility::FullSize);
  EXPECT_NEAR((path.world_T_robot(path.iterations() - 1).translation - Eigen::Vector2d(0, 0)).norm(), 0,
              kPathTolerance);
}

TEST(PlanarMapFile, MapDHasTheSpecsPiecesAndLoop) {
  const sim::PlanarMap map = read_planar_map(map_file("d_office_loop.json"));
  // Inner bottom: [3.5, 7.5] [8.5, 12.5] [13.5, 17.5] [18.5, 22.5] [23.5, 26.5] at z = 3, facing −z.
  const double inner_bottom[][2] = {{3.5, 7.5}, {8.5, 12.5}, {13.5, 17.5}, {18.5, 22.5}, {23.5, 26.5}};
  for (int i = 0; i < 5; ++i) {
    const sim::Wall& w = map.world.walls[20 + i];
    EXPECT_EQ(std::min(w.a.x(), w.b.x()), inner_bottom[i][0]);
    EXPECT_EQ(std::max(w.a.x(), w.b.x()), inner_bottom[i][1]);
    EXPECT_EQ(w.normal(), Eigen::Vector2d(0, -1));
  }
  const sim::PlanarPath path(map.path);
  // One loop: 88 units at 0.05 and four quarter turns at 1.5°; then 22 units and one turn.
  EXPECT_EQ(path.iterations(), 1 + 1760 + 240 + 440 + 60);
  EXPECT_NEAR((path.world_T_robot(path.iterations() - 1).translation - Eigen::Vector2d(28.5, 10)).norm(), 0,
              kPathTolerance);
  EXPECT_NEAR((path.world_T_robot(2000).translation - Eigen::Vector2d(15, 1.5)).norm(), 0, kPathTolerance)
      << "the first loop closes";
}

TEST(PlanarMapFile, MapEAtTheFirstCornerSeesOnlyThePartialEastWall) {
  // 's check on Map E: at (21.5, 2.5) facing +x only the end wall is visible, partially.
  sim::PlanarMap map = read_planar_map(map_file("e_motion_room.json"));
  map.sensor.noise = sim::PlaneNoiseOptions::none();
  const sim::PlanarSimulator simulator(map, 1);
  const int corner = simulator.path().operation_ends()[0];
  const sim::PlaneSimFrame f = simulator.frame(corner);
  EXPECT_EQ(f.truth.world_T_robot.translation, Eigen::Vector2d(21.5, 2.5));
  ASSERT_EQ(f.truth.planes.size(), 1u);
  EXPECT_EQ(f.truth.planes[0].wall_id, 1) << "the east wall x = 24";
  EXPECT_FALSE(f.truth.planes[0].a_is_wall_end);
  EXPECT_FALSE(f.truth.planes[0].b_is_wall_end);
}

TEST(PlanarMapFile, MapE1HasMapEsWalls) {
  const sim::PlanarMap e = read_planar_map(map_file("e_motion_room.json"));
  const sim::PlanarMap e1 = read_planar_map(map_file("e1_first_corner.json"));
  ASSERT_EQ(e1.world.walls.size(), e.world.walls.size());
  for (std::size_t i = 0; i < e.world.walls.size(); ++i) {
    EXPECT_EQ(e1.world.walls[i].a, e.world.walls[i].a) << "wall " << i;
    EXPECT_EQ(e1.world.walls[i].b, e.world.walls[i].b) << "wall " << i;
  }
  EXPECT_EQ(e1.path.steps.size(), 3u);
}

TEST(PlanarMapFile, MapDE09HasMapDsWallsAndFirstSeesWall2OnlyInPart) {
  // E09's variant of Map D (plane 5, thesis Figs 80/81): the same walls, the start turned round so
  // wall 2 is first seen cut by the frustum, and the robot back at the start facing +x after its
  // in-place turn, where Map D's own loop begins.
  const sim::PlanarMap d = read_planar_map(map_file("d_office_loop.json"));
  sim::PlanarMap e09 = read_planar_map(map_file("d_office_loop_e09.json"));
  ASSERT_EQ(e09.world.walls.size(), d.world.walls.size());
  for (std::size_t i = 0; i < d.world.walls.size(); ++i) {
    EXPECT_EQ(e09.world.walls[i].a, d.world.walls[i].a) << "wall " << i;
    EXPECT_EQ(e09.world.walls[i].b, d.world.walls[i].b) << "wall " << i;
  }
  e09.sensor.noise = sim::PlaneNoiseOptions::none();
  e09.sensor.frustum = sim::ViewingFrustum::large();
  const sim::PlanarSimulator simulator(e09, 1);
  const sim::PlaneSimFrame first = simulator.frame(0);
  const auto wall2 =
      std::find_if(first.truth.planes.begin(), first.truth.planes.end(), [](const auto& p) { return p.wall_id == 2; });
  ASSERT_NE(wall2, first.truth.planes.end()) << "wall 2 is in view at the start";
  EXPECT_NE(wall2->a_is_wall_end, wall2->b_is_wall_end) << "one end real, one cut by the frustum";
  const int turned = simulator.path().operation_ends()[0];
  EXPECT_NEAR((simulator.frame(turned).truth.world_T_robot.translation - Eigen::Vector2d(15, 1.5)).norm(), 0,
              kPathTolerance);
  EXPECT_NEAR(std::abs(wrap_angle(simulator.frame(turned).truth.world_T_robot.heading)), 0, 1e-9);
}

TEST(PlanarMapFile, SmallValidMapLoadsWithDefaults) {
  const sim::PlanarMap map = parse_planar_map(map_text(), "small.json");
  EXPECT_EQ(map.name, "small");
  EXPECT_EQ(map.world.walls[1].height, 2.5);
  EXPECT_EQ(map.sensor.mode, sim::PlaneVisibility::Frustum);
  EXPECT_EQ(map.path.speed, 0.05);
}

TEST(PlanarMapFile, ZeroLengthWallNamesTheEnd) {
  EXPECT_EQ(error_of(map_text(R"({"a": [5, -1], "b": [5, 1], "facing": "-x"})",
                              R"({"a": [6, 1], "b": [6, 1], "facing": "-x"})")),
            "m.json:4: walls[1].b: equals a [6, 1]; a wall needs two distinct ends");
}

TEST(PlanarMapFile, NumberBeyondADoubleIsRejectedAtItsLine) {
  // JSON has no NaN or infinity; a wall end that overflows is the nearest thing (the sim's
  // check() rejects non-finite ends of walls built in code: PlanarWorld.CheckNamesTheWallAndTheProblem).
  EXPECT_EQ(error_of(map_text(R"({"a": [1e400, -1], "b": [5, 1], "facing": "-x"})")),
            "m.json:3: walls[0].a[0]: number too large for a double: 1e400");
}

TEST(PlanarMapFile, WallWithoutFacingSideIsRejected) {
  EXPECT_EQ(
      error_of(map_text(R"({"a": [5, -1], "b": [5, 1], "facing": "-x"})", R"({"a": [6, 1], "b": [6, 2]})")),
      "m.json:4: walls[1].facing: is missing; give the side the wall's front looks to: \"+x\", \"-x\", \"+z\", \"-z\" "
      "or a direction [x, z]");
}

TEST(PlanarMapFile, FacingAlongTheWallIsRejected) {
  EXPECT_EQ(error_of(map_text(R"({"a": [5, -1], "b": [5, 1], "facing": "+z"})")),
            "m.json:3: walls[0].facing: runs along the wall; it must point to one side of it");
  EXPECT_EQ(error_of(map_text(R"({"a": [5, -1], "b": [5, 1], "facing": "front"})")),
            "m.json:3: walls[0].facing: expected \"+x\", \"-x\", \"+z\", \"-z\" or a direction [x, z], got \"front\"");
}

TEST(PlanarMapFile, UnknownKeyIsRejected) {
  EXPECT_EQ(error_of(map_text(R"({"a": [5, -1], "b": [5, 1], "facing": "-x", "heigth": 3})")),
            "m.json:3: walls[0].heigth: unknown key; expected one of a, b, facing, one_sided, scripted_windows");
}

TEST(PlanarMapFile, EmptyPathIsRejected) {
  EXPECT_EQ(error_of(map_text(R"({"a": [5, -1], "b": [5, 1], "facing": "-x"})",
                              R"({"a": [6, 1], "b": [6, 2], "facing": "-x"})", "[]")),
            "m.json:8: path.steps: is empty; a path needs at least one MOVE, TURN or ARC");
}

TEST(PlanarMapFile, BadStepsNameTheStep) {
  const std::string wall0 = R"({"a": [5, -1], "b": [5, 1], "facing": "-x"})",
                    wall1 = R"({"a": [6, 1], "b": [6, 2], "facing": "-x"})";
  EXPECT_EQ(
      error_of(map_text(wall0, wall1, R"(["MOVE 1", "MOV 4"])")),
      "m.json:8: path.steps[1]: expected \"MOVE <distance>\", \"TURN <degrees>\" or \"ARC <distance> <degrees>\", "
      "got \"MOV 4\"");
  EXPECT_EQ(error_of(map_text(wall0, wall1, R"(["MOVE -1"])")),
            "m.json:8: path.steps[0].distance: must be > 0, got -1");
  EXPECT_EQ(error_of(map_text(wall0, wall1, R"(["TURN +90", "ARC 2 -45"])")), "no error");
}

TEST(PlanarMapFile, PathThatNeverSeesTwoWallsIsRejected) {
  // Both walls behind the robot, which drives away from them.
  EXPECT_EQ(error_of(map_text(R"({"a": [-5, -1], "b": [-5, 1], "facing": "+x"})",
                              R"({"a": [-6, 1], "b": [-6, 2], "facing": "+x"})")),
            "m.json:6: path: never sees two walls at once with the map's sensor (mode frustum); the algorithm relates "
            "walls only through the ones it sees together");
}

// A path through a wall (or out of the room) ran with most poses wrong; it is refused with the
// step, its loop and the wall. Running along a wall or touching it is clearance, not crossing.
TEST(PlanarMapFile, PathThroughAWallNamesTheStepAndTheWall) {
  const std::string wall0 = R"({"a": [5, -1], "b": [5, 1], "facing": "-x"})",
                    wall1 = R"({"a": [6, 1], "b": [6, 2], "facing": "-x"})";
  EXPECT_EQ(error_of(map_text(wall0, wall1, R"(["MOVE 1", "MOVE 9"])"))
                .rfind("m.json:8: path.steps[1]: runs through walls[0] at (5, 0), loop 1, after iteration ", 0),
            0u)
      << error_of(map_text(wall0, wall1, R"(["MOVE 1", "MOVE 9"])"));
  EXPECT_EQ(error_of(map_text(wall0, wall1, R"(["MOVE 5"])")), "no error");  // stops on the wall
  EXPECT_EQ(error_of(map_text(wall0, wall1, R"(["TURN 90", "MOVE 1", "TURN -90", "MOVE 5"])")),
            "no error");  // ends on the line of wall 0, past its end
  EXPECT_EQ(error_of(map_text(wall0, wall1, R"(["ARC 12.6 -45"])"))
                .rfind("m.json:8: path.steps[0]: runs through walls[0] at (", 0),
            0u)
      << error_of(map_text(wall0, wall1, R"(["ARC 12.6 -45"])"));
}

TEST(PlanarMapFile, EveryShippedPathStaysClearOfItsWallsAndWithinTheMap) {
  for (const auto& entry : std::filesystem::directory_iterator(test::source_path("scenarios/maps"))) {
    const sim::PlanarMap map = read_planar_map(entry.path());
    EXPECT_FALSE(sim::first_wall_crossing(map, sim::PlanarPath(map.path))) << entry.path();
    EXPECT_FALSE(sim::first_exit_from_map(map, sim::PlanarPath(map.path))) << entry.path();
  }
}

// Out of the map: farther from every wall's extent than the sensor reaches (the small frustum's
// far corners, about 10.6 here), where nothing the map holds can be seen.
TEST(PlanarMapFile, PathLeavingTheMapNamesTheStepAndWhere) {
  const std::string wall0 = R"({"a": [5, -1], "b": [5, 1], "facing": "-x"})",
                    wall1 = R"({"a": [6, 1], "b": [6, 2], "facing": "-x"})";
  const std::string away = error_of(map_text(wall0, wall1, R"(["MOVE 4", "TURN 180", "MOVE 40"])"));
  EXPECT_EQ(away.rfind("m.json:8: path.steps[2]: leaves the map at (-36, ", 0), 0u) << away;
  EXPECT_NE(away.find("within its sensor's reach of the walls"), std::string::npos) << away;
  EXPECT_EQ(error_of(map_text(wall0, wall1, R"(["MOVE 4", "TURN 180", "MOVE 4"])")), "no error");
}

TEST(PlanarMapFile, MoreWallsThanTheLimitAreRefusedByTheirCount) {
  std::string walls;
  for (std::size_t i = 0; i <= kMaxPlanarWalls; ++i)
    walls += std::string(i ? ",\n" : "") + R"({"a": [5, )" + std::to_string(i) + R"(], "b": [5, )" +
             std::to_string(i + 1) + R"(], "facing": "-x"})";
  EXPECT_EQ(error_of("{\"walls\": [\n" + walls + "],\n \"path\": {}}"),
            "m.json:1: walls: has 10001; a map may have at most 10000 walls");
}

// A 10-million-step path that never comes near two walls took 107 s to refuse; walls out of the
// sensor's reach of a whole operation are set aside, so the time follows the map, not the path.
TEST(PlanarMapFile, LongPathNeverNearTwoWallsIsRefusedQuickly) {
  const auto start = std::chrono::steady_clock::now();
  const std::string text =
      "{\n"
      "  \"walls\": [\n"
      "    {\"a\": [1e7, 30], \"b\": [10000006, 30], \"facing\": \"-z\"},\n"
      "    {\"a\": [-1, -3], \"b\": [-1, 3], \"facing\": \"+x\"}\n"
      "  ],\n"
      "  \"path\": {\n"
      "    \"start\": {\"x\": 0, \"z\": 0, \"heading_deg\": 0}, \"speed\": 1,\n"
      "    \"steps\": [\"MOVE 9999990\"]\n"
      "  }\n"
      "}\n";
  EXPECT_NE(error_of(text).find("m.json:6: path: never sees two walls at once"), std::string::npos) << error_of(text);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), test::kRefusalSeconds);
}

// Two walls beside a long path, within the sensor's reach but outside its field of view: every
// iteration needs a sensor frame, so the search stops at its stated limit instead of running on.
TEST(PlanarMapFile, LongPathBesideWallsItNeverSeesStopsAtTheWorkLimit) {
  const auto start = std::chrono::steady_clock::now();
  const std::string text =
      "{\n"
      "  \"walls\": [\n"
      "    {\"a\": [-1e7, 7.5], \"b\": [1e7, 7.5], \"facing\": \"-z\"},\n"
      "    {\"a\": [-1e7, -7.5], \"b\": [1e7, -7.5], \"facing\": \"+z\"}\n"
      "  ],\n"
      "  \"path\": {\n"
      "    \"start\": {\"x\": 0, \"z\": 0, \"heading_deg\": 0}, \"speed\": 0.1,\n"
      "    \"steps\": [\"MOVE 999000\"]\n"
      "  }\n"
      "}\n";
  const std::string e = error_of(text);
  EXPECT_EQ(e.rfind("m.json:6: path: no iteration up to ", 0), 0u) << e;
  EXPECT_NE(e.find(" sees 2 walls at once, and searching the rest of the path would exceed the limit of 100000000 "
                   "wall tests: shorten the path"),
            std::string::npos)
      << e;
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), test::kRefusalSeconds);
}

TEST(PlanarMapFile, BadSensorHintIsRejected) {
  std::string text = map_text();
  text.insert(text.rfind('}'), "  ,\"sensor\": {\"mode\": \"always\"}\n");
  EXPECT_EQ(error_of(text),
            "m.json:10: sensor.mode: expected frustum, full_size, always_visible or scripted, got \"always\"");
}

TEST(PlanarMapFile, MissingFileIsAnInputError) {
  try {
    read_planar_map("/nonexistent/map.json");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.problem(), "file not found");
  }
}

}  // namespace
}  // namespace relslam::eval
