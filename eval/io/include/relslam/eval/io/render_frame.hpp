#pragma once
// What every picture of a run shares — which part of the world it shows and how large it is
// drawn — whatever it draws: the point map (map_render.hpp), the planar map (planar_render.hpp)
// and the run overview (run_overview.hpp). Its own header so none of them includes another.

#include <optional>

namespace relslam::eval {

enum class RenderView { Top, Side };  // top: world z right, x up (seen from +y); side: z right, y up

// What part of the world the picture shows.
struct RenderFrame {
  double center_u = 0, center_v = 0;  // picture centre in world units (top: z, x; side: z, y)
  double span = 100;                  // world units across the picture's wider side
};

struct RenderOptions {
  int width = 1280;  // pixels
  int height = 960;
  RenderView view = RenderView::Top;
  // Point and group labels (thesis Fig 129). Unset: only when at most this many landmarks are
  // in the picture [C], so a whole figure eight stays readable.
  std::optional<bool> labels;
  int auto_label_limit = 250;
};

}  // namespace relslam::eval
