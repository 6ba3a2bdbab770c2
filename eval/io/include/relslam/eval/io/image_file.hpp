#pragma once
// A picture to a file: the one exit of every renderer (map, planar map, overview), kept apart
// from them so drawing code does not need the image codecs.

#include <string>

namespace cv {
class Mat;
}

namespace relslam::eval {

// Writes a picture in the format its extension names (.png, .jpg, ...). Throws InputError at
// --out when it cannot.
void write_image(const std::string& file, const cv::Mat& image);

}  // namespace relslam::eval
