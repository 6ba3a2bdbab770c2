#include "relslam/eval/io/image_file.hpp"

#include "relslam/eval/config/input_error.hpp"

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

namespace relslam::eval {

void write_image(const std::string& file, const cv::Mat& image) {
  bool ok = false;
  try {
    ok = cv::imwrite(file, image);
  } catch (const cv::Exception& e) {
    throw InputError(file, 0, "--out", std::string("cannot write an image here: ") + e.what());
  }
  if (!ok) throw InputError(file, 0, "--out", "cannot write an image here (a known image extension such as .png?)");
}

}  // namespace relslam::eval
