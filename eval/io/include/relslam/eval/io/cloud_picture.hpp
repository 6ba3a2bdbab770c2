#pragma once
// A picture of a point cloud coloured by plane: for `relslam extract`, to see what each
// extractor made of a frame.

#include "relslam/eval/io/point_cloud_rawlog.hpp"

#include <string>
#include <vector>

namespace relslam::eval {

// plane_of[i]: the plane of point i (0, 1, ...), -1 for none. An organised frame is drawn as its
// image (black: no return, grey: no plane); any other as seen from above (x to the left, z up
// the picture), scaled to its extent. Plane k gets the k-th colour of a fixed palette. PNG by
// the file's extension; throws InputError when it cannot be written.
void write_cloud_picture(const std::string& file, const PointCloudFrame& frame, const std::vector<int>& plane_of);

}  // namespace relslam::eval
