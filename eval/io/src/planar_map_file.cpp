#include "relslam/eval/io/planar_map_file.hpp"

#include "relslam/core/option_issue.hpp"
#include "relslam/eval/config/input_error.hpp"
#include "relslam/eval/config/json_document.hpp"
#include "relslam/sim/planar_sight.hpp"

#include <charconv>
#include <cmath>
#include <initializer_list>
#include <numbers>
#include <optional>
#include <sstream>
#include <string_view>

namespace relslam::eval {
namespace {

using nlohmann::json;

constexpr double kDegree = std::numbers::pi / 180.0;
constexpr const char* kFacingChoices = "\"+x\", \"-x\", \"+z\", \"-z\" or a direction [x, z]";
constexpr const char* kStepForms = "\"MOVE <distance>\", \"TURN <degrees>\" or \"ARC <distance> <degrees>\"";

std::string join(const std::string& prefix, const std::string& key) {
  return prefix.empty() ? key : prefix + "." + key;
}
std::string element(const std::string& list, std::size_t i) { return list + "[" + std::to_string(i) + "]"; }

// A number written the JSON way, with an optional leading '+' ("TURN +90").
std::optional<double> parse_number(std::string_view token) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  double value = 0;
  const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (error != std::errc() || end != token.data() + token.size()) return std::nullopt;
  return value;
}

// "MOVE 4", "TURN -90", "ARC 5 90": the operations of thesis 4.4.2, angles in degrees.
std::optional<sim::PathOperation> parse_step(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> words;
  for (std::string word; in >> word;) words.push_back(word);
  std::vector<double> values;
  for (std::size_t i = 1; i < words.size(); ++i) {
    const std::optional<double> value = parse_number(words[i]);
    if (!value) return std::nullopt;
    values.push_back(*value);
  }
  if (words.empty()) return std::nullopt;
  if (words[0] == "MOVE" && values.size() == 1) return sim::PathOperation::move(values[0]);
  if (words[0] == "TURN" && values.size() == 1) return sim::PathOperation::turn(values[0] * kDegree);
  if (words[0] == "ARC" && values.size() == 2) return sim::PathOperation::arc(values[0], values[1] * kDegree);
  return std::nullopt;
}

// Reads one document into a PlanarMap; every error names the file, the line and the field.
class MapReader {
 public:
  explicit MapReader(const JsonDocument& doc) : doc_(doc) {}

  sim::PlanarMap read() {
    const json& root = doc_.value;
    if (!root.is_object()) throw InputError(doc_.file, 1, "", "a map file must be a JSON object");
    only_keys(root, "", {"name", "description", "wall_height", "walls", "path", "sensor"});
    sim::PlanarMap map;
    map.name = root.contains("name") ? text(root["name"], "name") : std::filesystem::path(doc_.file).stem().string();
    if (root.contains("description")) map.description = text(root["description"], "description");
    const double height =
        root.contains("wall_height") ? number(root["wall_height"], "wall_height") : sim::Wall{}.height;

    const json& walls = member(root, "", "walls");
    if (!walls.is_array()) fail("walls", "expected a list of walls, got " + walls.dump());
    if (walls.size() < 2) fail("walls", "has " + std::to_string(walls.size()) + "; a map needs at least two walls");
    if (walls.size() > kMaxPlanarWalls)
      fail("walls", "has " + std::to_string(walls.size()) + "; a map may have at most " +
                        std::to_string(kMaxPlanarWalls) + " walls");
    std::vector<Eigen::Vector2d> facings;
    for (std::size_t i = 0; i < walls.size(); ++i) map.world.walls.push_back(read_wall(walls[i], i, height, facings));
    // Ends, heights and windows are checked before `facing` orders the ends: a zero-length or
    // non-finite wall has no sides to face.
    report(sim::check(map.world), "");
    for (std::size_t i = 0; i < walls.size(); ++i)
      orient(map.world.walls[i], facings[i], join(element("walls", i), "facing"));

    map.path = read_path(member(root, "", "path"));
    report(sim::check(map.path), "path.");
    if (root.contains("sensor")) read_sensor(root["sensor"], map.sensor);
    report(sim::check(map.sensor), "sensor.");

    check_along_path(map);
    return map;
  }

 private:
  // The path must stay within reach of the map, clear of its walls, and see two of them at
  // once; all in time that grows with the map, not with the path's length (planar_sight.hpp).
  void check_along_path(const sim::PlanarMap& map) const {
    const sim::PlanarPath path(map.path);
    std::optional<sim::WallCrossing> crossing;
    std::optional<int> seeing;
    const std::optional<sim::MapExit> exit = sim::first_exit_from_map(map, path);
    if (exit) {
      const sim::OperationPlace place = sim::operation_place(map.path, exit->operation);
      fail("path." + place.field,
           "leaves the map at (" + format_number(exit->at.x()) + ", " + format_number(exit->at.y()) + ")" +
               (place.loop > 0 ? ", loop " + std::to_string(place.loop) : "") + ", iteration " +
               std::to_string(exit->iteration) + ": the robot must stay within its sensor's reach of the walls, x " +
               format_number(exit->low.x()) + " to " + format_number(exit->high.x()) + ", z " +
               format_number(exit->low.y()) + " to " + format_number(exit->high.y()));
    }
    try {
      crossing = sim::first_wall_crossing(map, path);
      if (!crossing) seeing = sim::first_iteration_seeing(map, path, 2);
    } catch (const OptionError& e) {  // the path is too long to check
      fail(e.field(), e.problem());
    }
    if (crossing) {
      const sim::OperationPlace place = sim::operation_place(map.path, crossing->operation);
      fail("path." + place.field, "runs through walls[" + std::to_string(crossing->wall) + "] at (" +
                                      format_number(crossing->at.x()) + ", " + format_number(crossing->at.y()) + ")" +
                                      (place.loop > 0 ? ", loop " + std::to_string(place.loop) : "") +
                                      ", after iteration " + std::to_string(crossing->before) +
                                      ": the robot must stay inside the walls (a wall may be touched, not crossed)");
    }
    if (!seeing)
      fail("path", "never sees two walls at once with the map's sensor (mode " +
                       std::string(sim::to_string(map.sensor.mode)) +
                       "); the algorithm relates walls only through the ones it sees together");
  }

  [[noreturn]] void fail(const std::string& field, const std::string& problem) const {
    throw InputError(doc_.file, line_near(field), field, problem);
  }

  // The line of `field`, or of the nearest enclosing key the document recorded (a check()
  // field such as "path.steps[2].distance" lies inside the string "path.steps[2]").
  int line_near(std::string field) const {
    while (!field.empty()) {
      if (const int line = doc_.line_of(field); line > 0) return line;
      const std::size_t cut = field.find_last_of(".[");
      field.resize(cut == std::string::npos ? 0 : cut);
    }
    return 0;
  }

  void report(const std::vector<OptionIssue>& issues, const std::string& prefix) const {
    if (!issues.empty()) fail(prefix + issues.front().field, issues.front().problem);
  }

  void only_keys(const json& object, const std::string& path, std::initializer_list<const char*> allowed) const {
    for (const auto& [key, value] : object.items()) {
      bool known = false;
      for (const char* name : allowed) known = known || key == name;
      if (known) continue;
      std::string list;
      for (const char* name : allowed) list += (list.empty() ? "" : ", ") + std::string(name);
      fail(join(path, key), "unknown key; expected one of " + list);
    }
  }

  const json& member(const json& object, const std::string& path, const char* key, const std::string& hint = "") const {
    if (!object.contains(key)) fail(join(path, key), "is missing" + (hint.empty() ? "" : "; " + hint));
    return object[key];
  }

  double number(const json& value, const std::string& field) const {
    if (!value.is_number()) fail(field, "expected a number, got " + value.dump());
    return value.get<double>();
  }

  int integer(const json& value, const std::string& field) const {
    if (!value.is_number_integer()) fail(field, "expected an integer, got " + value.dump());
    return value.get<int>();
  }

  std::string text(const json& value, const std::string& field) const {
    if (!value.is_string()) fail(field, "expected a string, got " + value.dump());
    return value.get<std::string>();
  }

  const json& object(const json& value, const std::string& field) const {
    if (!value.is_object()) fail(field, "expected an object, got " + value.dump());
    return value;
  }

  Eigen::Vector2d point(const json& value, const std::string& field) const {
    if (!value.is_array() || value.size() != 2 || !value[0].is_number() || !value[1].is_number())
      fail(field, "expected a point [x, z], got " + value.dump());
    return {value[0].get<double>(), value[1].get<double>()};
  }

  // The side the front looks to: an axis or any direction not along the wall.
  Eigen::Vector2d facing(const json& value, const std::string& field) const {
    if (value.is_string()) {
      const std::string name = value.get<std::string>();
      if (name == "+x") return {1, 0};
      if (name == "-x") return {-1, 0};
      if (name == "+z") return {0, 1};
      if (name == "-z") return {0, -1};
    } else if (value.is_array() && value.size() == 2 && value[0].is_number() && value[1].is_number()) {
      const Eigen::Vector2d direction(value[0].get<double>(), value[1].get<double>());
      if (direction.allFinite() && direction != Eigen::Vector2d::Zero()) return direction;
    }
    fail(field, std::string("expected ") + kFacingChoices + ", got " + value.dump());
  }

  sim::Wall read_wall(const json& value, std::size_t i, double height, std::vector<Eigen::Vector2d>& facings) const {
    const std::string field = element("walls", i);
    object(value, field);
    only_keys(value, field, {"a", "b", "facing", "one_sided", "scripted_windows"});
    // Position in the file is the wall's id: map order is output order, as the thesis's simulator (Fig. 94).
    sim::Wall wall = sim::Wall::between(static_cast<int>(i), point(member(value, field, "a"), join(field, "a")),
                                        point(member(value, field, "b"), join(field, "b")));
    wall.height = height;
    facings.push_back(facing(
        member(value, field, "facing", std::string("give the side the wall's front looks to: ") + kFacingChoices),
        join(field, "facing")));
    if (value.contains("one_sided")) {
      if (!value["one_sided"].is_boolean())
        fail(join(field, "one_sided"), "expected true or false, got " + value["one_sided"].dump());
      wall.one_sided = value["one_sided"].get<bool>();
    }
    if (value.contains("scripted_windows")) {
      const std::string list = join(field, "scripted_windows");
      const json& windows = value["scripted_windows"];
      if (!windows.is_array()) fail(list, "expected a list of [first, last] iteration windows, got " + windows.dump());
      for (std::size_t j = 0; j < windows.size(); ++j) {
        const json& w = windows[j];
        if (!w.is_array() || w.size() != 2 || !w[0].is_number_integer() || !w[1].is_number_integer())
          fail(element(list, j), "expected [first, last] iterations, got " + w.dump());
        wall.scripted_windows.push_back({w[0].get<int>(), w[1].get<int>()});
      }
    }
    return wall;
  }

  // Orders the ends so that the front normal Rot(+90°)(b − a) points to the facing side.
  void orient(sim::Wall& wall, const Eigen::Vector2d& facing, const std::string& field) const {
    const double side = wall.normal().dot(facing.normalized());
    if (std::abs(side) < 1e-9) fail(field, "runs along the wall; it must point to one side of it");
    if (side < 0) std::swap(wall.a, wall.b);
  }

  std::vector<sim::PathOperation> steps(const json& value, const std::string& field) const {
    if (!value.is_array()) fail(field, std::string("expected a list of ") + kStepForms + ", got " + value.dump());
    std::vector<sim::PathOperation> operations;
    for (std::size_t i = 0; i < value.size(); ++i) {
      const std::optional<sim::PathOperation> op =
          value[i].is_string() ? parse_step(value[i].get<std::string>()) : std::nullopt;
      if (!op) fail(element(field, i), std::string("expected ") + kStepForms + ", got " + value[i].dump());
      operations.push_back(*op);
    }
    return operations;
  }

  sim::PathProgram read_path(const json& value) const {
    object(value, "path");
    only_keys(value, "path", {"start", "speed", "turn_rate_deg", "loops", "steps", "then"});
    sim::PathProgram path;
    const json& start = object(member(value, "path", "start"), "path.start");
    only_keys(start, "path.start", {"x", "z", "heading_deg"});
    path.start =
        PlanarPose::from(number(member(start, "path.start", "x"), "path.start.x"),
                         number(member(start, "path.start", "z"), "path.start.z"),
                         number(member(start, "path.start", "heading_deg"), "path.start.heading_deg") * kDegree);
    if (value.contains("speed")) path.speed = number(value["speed"], "path.speed");
    if (value.contains("turn_rate_deg"))
      path.turn_rate_rad = number(value["turn_rate_deg"], "path.turn_rate_deg") * kDegree;
    if (value.contains("loops")) path.loops = integer(value["loops"], "path.loops");
    path.steps = steps(member(value, "path", "steps"), "path.steps");
    if (value.contains("then")) path.then = steps(value["then"], "path.then");
    return path;
  }

  // The sensor the map was made for, as a hint a run may override.
  void read_sensor(const json& value, sim::PlaneSensorOptions& sensor) const {
    object(value, "sensor");
    only_keys(value, "sensor", {"mode", "frustum", "noise"});
    if (value.contains("mode")) {
      const std::optional<sim::PlaneVisibility> mode = sim::parse_plane_visibility(text(value["mode"], "sensor.mode"));
      if (!mode)
        fail("sensor.mode", "expected frustum, full_size, always_visible or scripted, got " + value["mode"].dump());
      sensor.mode = *mode;
    }
    if (value.contains("frustum")) {
      const std::optional<sim::ViewingFrustum> frustum = sim::frustum_preset(text(value["frustum"], "sensor.frustum"));
      if (!frustum) fail("sensor.frustum", "expected small or large, got " + value["frustum"].dump());
      sensor.frustum = *frustum;
    }
    if (value.contains("noise")) {
      const std::optional<sim::PlaneNoiseModel> model =
          sim::parse_plane_noise_model(text(value["noise"], "sensor.noise"));
      if (!model)
        fail("sensor.noise", "expected none, gaussian, uniform or three_valued_rotation, got " + value["noise"].dump());
      sensor.noise =
          *model == sim::PlaneNoiseModel::None ? sim::PlaneNoiseOptions::none() : sim::PlaneNoiseOptions::with_noise();
      sensor.noise.model = *model;
    }
  }

  const JsonDocument& doc_;
};

}  // namespace

sim::PlanarMap read_planar_map(const std::filesystem::path& file) { return MapReader(read_json_file(file)).read(); }

sim::PlanarMap parse_planar_map(const std::string& text, const std::string& file) {
  return MapReader(parse_json(text, file)).read();
}

namespace {

std::string numbers(std::initializer_list<double> values) {
  std::string out;
  for (double v : values) out += (out.empty() ? "" : ", ") + format_number(v);
  return "[" + out + "]";
}

std::string step_text(const sim::PathOperation& op) {
  switch (op.kind) {
    case sim::PathOperationKind::Move: return "MOVE " + format_number(op.distance);
    case sim::PathOperationKind::Turn: return "TURN " + format_number(op.angle_rad / kDegree);
    case sim::PathOperationKind::Arc: return "ARC " + format_number(op.distance) + " " + format_number(op.angle_rad / kDegree);
  }
  return "";
}

std::string steps_text(const std::vector<sim::PathOperation>& ops) {
  std::string out;
  for (const sim::PathOperation& op : ops) out += (out.empty() ? "" : ", ") + json(step_text(op)).dump();
  return "[" + out + "]";
}

// The preset's name when the frustum is one, else "" (the file then keeps the reader's default).
std::string preset_name(const sim::ViewingFrustum& f) {
  for (const char* name : {"small", "large"}) {
    const sim::ViewingFrustum p = *sim::frustum_preset(name);
    if (p.half_angle_rad == f.half_angle_rad && p.near == f.near && p.far == f.far) return name;
  }
  return "";
}

}  // namespace

std::string planar_map_text(const sim::PlanarMap& map) {
  std::string out = "{\n  \"name\": " + json(map.name).dump() + ",\n  \"description\": " + json(map.description).dump() + ",\n";
  if (!map.world.walls.empty()) out += "  \"wall_height\": " + format_number(map.world.walls.front().height) + ",\n";
  out += "  \"walls\": [\n";
  for (std::size_t i = 0; i < map.world.walls.size(); ++i) {
    const sim::Wall& w = map.world.walls[i];
    const Eigen::Vector2d n = w.normal();
    out += "    {\"a\": " + numbers({w.a.x(), w.a.y()}) + ", \"b\": " + numbers({w.b.x(), w.b.y()}) +
           ", \"facing\": " + numbers({n.x(), n.y()}) + (w.one_sided ? "" : ", \"one_sided\": false") + "}" +
           (i + 1 < map.world.walls.size() ? ",\n" : "\n");
  }
  const sim::PathProgram& p = map.path;
  out += "  ],\n  \"path\": {\n    \"start\": {\"x\": " + format_number(p.start.translation.x()) +
         ", \"z\": " + format_number(p.start.translation.y()) +
         ", \"heading_deg\": " + format_number(p.start.heading / kDegree) + "},\n";
  out += "    \"speed\": " + format_number(p.speed) + ",\n    \"turn_rate_deg\": " +
         format_number(p.turn_rate_rad / kDegree) + ",\n    \"loops\": " + std::to_string(p.loops) + ",\n";
  out += "    \"steps\": " + steps_text(p.steps) + (p.then.empty() ? "" : ",\n    \"then\": " + steps_text(p.then)) + "\n  },\n";
  const std::string preset = preset_name(map.sensor.frustum);
  out += "  \"sensor\": {\"mode\": " + json(std::string(sim::to_string(map.sensor.mode))).dump() +
         (preset.empty() ? "" : ", \"frustum\": \"" + preset + "\"") + ", \"noise\": " +
         json(std::string(sim::to_string(map.sensor.noise.model))).dump() + "}\n}\n";
  return out;
}

}  // namespace relslam::eval
