#pragma once
// Everything that defines a simulated world and sensor, with one documented default each and,
// beside each struct, its description: key name, help and checks per field
// (core/option_fields.hpp). Part of relslam/sim: no I/O. Tags: [T] thesis-stated,
// [I] inferred, [C] chosen (thesis 6.6.1).

#include "relslam/core/option_fields.hpp"
#include "relslam/core/option_issue.hpp"
#include "relslam/sim/frustum.hpp"

#include <optional>
#include <string_view>
#include <vector>

namespace relslam::sim {

enum class PathKind {
  FigureEight,  // the Chapter 6 test track: two lobes, gradual incline (thesis 6.6.1)
  Line,         // straight and flat, for the no-turn EKF comparison (thesis 6.7.2)
  Stationary,   // the robot never moves; it looks down the straight-line field (thesis 6.7.2)
};
std::string_view to_string(PathKind kind);
std::optional<PathKind> parse_path_kind(std::string_view name);

// Landmarks that move independently of the viewpoint (thesis 6.5.3, 6.7.3).
// Motion [C]: p(k) = p0 + amplitude·(sin(2πk/T1+φ1), vertical_ratio·sin(2πk/T2+φ2), sin(2πk/T3+φ3)),
// periods uniform in [period_min, period_max] iterations, phases uniform in [0, 2π).
struct DynamicOptions {
  // Number of points made dynamic, chosen among the points visible at iteration 0 (the
  // thesis's dynamic RltPoints 18 and 24 were seen early) [T count 2 for S-DYN, I choice].
  int count = 0;
  // ...and still in view this many iterations later (anchor positions, noise-free), so each
  // is seen long enough to be put in a final group and tested (thesis Figs 157-162) [C].
  int count_visible_for = 100;
  // Share of all points made dynamic, chosen uniformly; used instead of `count` [T 3 % in Fig 117].
  double fraction = 0.0;
  double amplitude = 4.0;       // units; several matching bounds, well above the noise [C]
  double vertical_ratio = 0.3;  // vertical motion is smaller so movers mostly stay in the band [C]
  double period_min = 150.0;    // iterations; slow enough that local matching still tracks them [C]
  double period_max = 400.0;    // iterations [C]
};

// The scenario keys of DynamicOptions (sim.dynamic.*).
void describe(OptionsOf<DynamicOptions> auto& d, auto& f) {
  f.field("count", d.count, "dynamic points chosen among those visible at iteration 0 (S-DYN: 2)", at_least(0));
  f.field("count_visible_for", d.count_visible_for,
          "counted movers are seen at iteration 0 and this many iterations later", at_least(0));
  f.field("fraction", d.fraction, "share of all points made dynamic (S-DYN3: 0.03)", at_least(0.0), at_most(1.0),
          holds(!(d.count > 0 && d.fraction > 0), "set either dynamic.count or dynamic.fraction, not both"));
  f.field("amplitude", d.amplitude, "dynamic wander amplitude, units", at_least(0.0),
          at_most(kMaxLength));
  f.field("vertical_ratio", d.vertical_ratio, "vertical amplitude as a share of the horizontal one", at_least(0.0),
          at_most(1000.0));
  f.field("period_min", d.period_min, "shortest wander period, iterations", above(0.0));
  f.field("period_max", d.period_max, "longest wander period, iterations", at_least(d.period_min));
}

struct SimOptions {
  PathKind path = PathKind::FigureEight;  // [T] figure eight is the main test track
  // Times round the figure eight (ignored when `iterations` is set). Also sets the length
  // of the line and stationary runs, one loop's worth of iterations each.
  int loops = 1;
  // Run length in iterations; overrides `loops` when set.
  std::optional<int> iterations;
  // Multiplies every path length (loop length, incline height, iterations per loop) but not
  // the sensor or the point band: 2 gives the "twice the size" figure eight of Fig 136 [T, C].
  double scale = 1.0;
  // Points per 100 units of path [T definition]; the points-per-frame knob of Figs 137–145.
  double density = 100.0;
  // Standard deviation of the white Gaussian noise on each axis of each observation [T white
  // Gaussian, C value]; applied before culling (thesis 6.6.1).
  double noise_sigma = 0.1;
  // Noise grows with range: sigma(r) = noise_sigma·(1 + r/far). Off in every thesis run [C].
  bool range_noise = false;

  double loop_length = 1145.0;     // units per figure-eight loop at scale 1 [T "about 1145"]
  int iterations_per_loop = 3800;  // at scale 1 [T "about 3800"]; fixes the step length
  // Height gained between the start and the crossing: the robot passes above its start after
  // the first lobe, so it cannot close the loop early [T shape, C value]. Must exceed twice
  // band_half_height so the two passes see disjoint points.
  double incline_height = 20.0;
  // Adds a small roll and pitch oscillation so all six degrees of freedom move [C].
  bool wobble = false;

  double band_half_width = 15.0;  // units either side of the path, horizontally [C]
  double band_half_height = 5.0;  // units above and below the path [T symmetric, C value]
  // The line field runs this far past the end of the line so the last frames are not empty [C].
  double line_margin = 110.0;

  Frustum frustum;
  DynamicOptions dynamic;
};

// Upper bounds that keep a typo from allocating the machine away: far above every thesis run
// (S-40 has 152,000 iterations; ρ = 550 has 6,298 points).
inline constexpr long long kMaxIterations = 100'000'000;
inline constexpr long long kMaxLandmarks = 20'000'000;
// Smallest sim.scale: a loop of 11.45 units in 38 iterations, far below the frustum's reach and
// every thesis run (1 and 2). Smaller scales have no use, and below 1/(2·iterations_per_loop) a
// loop rounds to zero iterations, whose step length is 0/0 (NaN truth poses).
inline constexpr double kMinScale = 0.01;

// The scenario keys of SimOptions (sim.*): help and checks per field.
void describe(OptionsOf<SimOptions> auto& o, auto& f) {
  f.choice("path", o.path, "robot path (thesis 6.6.1, 6.7.2)",
           {PathKind::FigureEight, PathKind::Line, PathKind::Stationary});
  f.field("loops", o.loops, "times round the figure eight; 1 loop = 3800 iterations", at_least(1));
  f.field("iterations", o.iterations, "run length in iterations; overrides sim.loops", at_least(1),
          at_most(kMaxIterations));
  f.field("scale", o.scale, "multiplies path lengths; 2 = the double-size eight (Fig 136)", at_least(kMinScale),
          at_most(1000.0),
          holds(o.scale * o.iterations_per_loop >= 1.0,
                "gives less than one iteration per loop: scale × iterations_per_loop must be at least 1"));
  f.field("density", o.density, "points per 100 units of path (thesis 6.6.2)", at_least(0.0));
  f.field("noise_sigma", o.noise_sigma, "std. deviation of white Gaussian noise per axis, units", at_least(0.0),
          at_most(kMaxLength));
  f.field("range_noise", o.range_noise, "noise grows with range: sigma·(1 + range/far)");
  f.field("loop_length", o.loop_length, "figure-eight loop length at scale 1, units", above(0.0),
          at_most(kMaxLength));
  f.field("iterations_per_loop", o.iterations_per_loop, "iterations per loop at scale 1; sets the speed", at_least(1));
  f.field("incline_height", o.incline_height, "height of the crossing above the start, units", at_least(0.0),
          at_most(kMaxLength));
  f.field("wobble", o.wobble, "add small roll and pitch oscillations (all 6 DOF move)");
  f.field("band_half_width", o.band_half_width, "point band extends this far left and right, units", at_least(0.0),
          at_most(kMaxLength));
  f.field("band_half_height", o.band_half_height, "point band extends this far up and down, units", at_least(0.0),
          at_most(kMaxLength));
  f.field("line_margin", o.line_margin, "line field runs this far past the end, units", at_least(0.0),
          at_most(kMaxLength));
  f.nested("frustum", o.frustum);
  f.nested("dynamic", o.dynamic);
}

// Every violated constraint; fields are paths inside SimOptions ("dynamic.count"): the
// description's checks, and the run's size bounded by kMaxIterations and kMaxLandmarks.
std::vector<OptionIssue> check(const SimOptions& options);

// What the options ask for, computed from them alone: check() bounds the run's size with these
// before anything is built, and Path and World size themselves with the same functions (options
// are the bottom of sim: they call nothing above them).

// Number of iterations the options ask for (loops or the explicit count).
long long iteration_count(const SimOptions& options);
// Length of one figure-eight loop at this scale, units.
double scaled_loop_length(const SimOptions& options);
// Arc length advanced per iteration: one loop in scale·iterations_per_loop iterations,
// constant speed.
double step_length(const SimOptions& options);
// Length of the centre line the point band is generated along (thesis 6.6.2): one loop, or the
// straight run plus line_margin.
double field_length(const SimOptions& options);
// Number of static points the band gets: density per 100 units times the field length.
long long landmark_count(const SimOptions& options);

}  // namespace relslam::sim
