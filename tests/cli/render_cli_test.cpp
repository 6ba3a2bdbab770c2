// relslam render: the replayed state drawn where the axes say, pictures of the asked size, a
// video with one frame per step, and bad requests refused with the option named.
#include "relslam/eval/io/map_render.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/videoio.hpp>

namespace relslam::eval {
namespace {

// Pixels of exactly this BGR colour.
int count_colour(const cv::Mat& image, cv::Vec3b colour) {
  int n = 0;
  for (int r = 0; r < image.rows; ++r)
    for (int c = 0; c < image.cols; ++c) n += image.at<cv::Vec3b>(r, c) == colour;
  return n;
}

const cv::Vec3b kBox(0, 160, 0);  // map point boxes

TEST(MapRender, TopViewPutsForwardRightAndLeftUp) {
  RenderScene scene;
  scene.landmarks = {{Eigen::Vector3d(0, 0, 40), 1, -1, true, false},   // 40 ahead (+z)
                     {Eigen::Vector3d(30, 0, 0), 2, -1, true, false}};  // 30 to the left (+x)
  RenderOptions options;
  options.width = 400;
  options.height = 400;
  options.labels = false;
  const cv::Mat image = render_map(scene, {0, 0, 100}, options);  // 4 pixels per unit, centre (200, 200)
  ASSERT_EQ(image.cols, 400);
  ASSERT_EQ(image.rows, 400);
  // A box is a 5x5 outline around its point: its left edge sits 2 pixels left of the point.
  EXPECT_EQ(image.at<cv::Vec3b>(200, 200 + 160 - 2), kBox);  // z = 40 -> 160 px right of centre
  EXPECT_EQ(image.at<cv::Vec3b>(200 - 120, 200 - 2), kBox);  // x = 30 -> 120 px above centre
  // Two 5x5 outlines and nothing else green above the legend.
  EXPECT_EQ(count_colour(image(cv::Rect(0, 0, 400, 270)), kBox), 2 * 16);
  options.view = RenderView::Side;
  scene.landmarks = {{Eigen::Vector3d(0, 10, 0), 1, -1, true, false}};  // 10 up (+y)
  EXPECT_EQ(render_map(scene, {0, 0, 100}, options).at<cv::Vec3b>(200 - 40, 200 - 2), kBox);
}

TEST(MapRender, FitEverythingHoldsEveryPoint) {
  RenderScene scene;
  scene.true_points = {{-50, 0, 10}, {20, 0, 300}};
  RenderOptions options;
  const RenderFrame f = fit_everything(scene, options);
  EXPECT_DOUBLE_EQ(f.center_u, 155);  // z
  EXPECT_DOUBLE_EQ(f.center_v, -15);  // x
  EXPECT_GE(f.span, 290);
  EXPECT_LT(f.span, 290 * 1.2);
}

class RenderCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new test::ScratchDir;
    const auto r = test::run_relslam({"run", test::source_path("scenarios/s-ekf-f8.json").string(), "--set",
                                      "sim.iterations=150", "--out", (*dir_ / "run").string(), "-q"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  static void TearDownTestSuite() { delete dir_; }
  static std::string run_dir() { return (*dir_ / "run").string(); }
  static std::string out(const std::string& name) { return (*dir_ / name).string(); }
  static test::ScratchDir* dir_;
};
test::ScratchDir* RenderCli::dir_ = nullptr;

TEST_F(RenderCli, DrawsTheReplayedMapAtTheAskedSize) {
  const auto r = test::run_relslam(
      {"render", run_dir(), "--iteration", "120", "--width", "640", "--height", "480", "--out", out("map.png"), "-q"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // The replay reached the very pose the run recorded: no warning.
  EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
  const cv::Mat image = cv::imread(out("map.png"));
  ASSERT_FALSE(image.empty());
  EXPECT_EQ(image.cols, 640);
  EXPECT_EQ(image.rows, 480);
  EXPECT_GT(count_colour(image, kBox), 100);  // the map's points
  // Drawing is deterministic: the same request gives the same bytes.
  ASSERT_EQ(test::run_relslam({"render", run_dir(), "--iteration", "120", "--width", "640", "--height", "480", "--out",
                               out("again.png"), "-q"})
                .exit_code,
            0);
  EXPECT_EQ(test::read_file(out("map.png")), test::read_file(out("again.png")));
}

TEST_F(RenderCli, DrawsTheEkfAndACloseUp) {
  const auto r = test::run_relslam(
      {"render", run_dir(), "--algorithm", "ekf6d", "--fit", "robot", "--view", "side", "--out", out("ekf.png"), "-q"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
  const cv::Mat image = cv::imread(out("ekf.png"));
  EXPECT_EQ(image.cols, 1280);
  EXPECT_EQ(image.rows, 960);
}

TEST_F(RenderCli, AVideoHasAFramePerStep) {
  const auto r = test::run_relslam(
      {"render", run_dir(), "--video", out("run.mp4"), "--every", "10", "--width", "320", "--height", "240", "-q"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  cv::VideoCapture video(out("run.mp4"));
  ASSERT_TRUE(video.isOpened());
  EXPECT_EQ(video.get(cv::CAP_PROP_FRAME_COUNT), 15);  // iterations 0, 10, ..., 140
  EXPECT_EQ(video.get(cv::CAP_PROP_FRAME_WIDTH), 320);
}

TEST_F(RenderCli, BadRequestsNameTheOption) {
  struct Case {
    std::vector<std::string> args;
    std::string expected;
  };
  test::ScratchDir empty;
  for (const Case& c : std::vector<Case>{
           {{"--iteration", "150", "--out", out("x.png")}, "--iteration: the run has iterations 0..149, got 150"},
           {{"--algorithm", "ekf2d", "--out", out("x.png")}, "--algorithm"},
           {{"--view", "front", "--out", out("x.png")}, "--view: top or side"},
           {{"--out", out("x.unknown")}, "--out"},
           {{}, "--out: give --out IMAGE, --video MP4, or both"},
       }) {
    std::vector<std::string> args = {"render", run_dir()};
    args.insert(args.end(), c.args.begin(), c.args.end());
    const auto r = test::run_relslam(args);
    EXPECT_EQ(r.exit_code, 2) << c.expected;
    EXPECT_NE(r.err.find(c.expected), std::string::npos) << r.err;
  }
  const auto r = test::run_relslam({"render", empty.path().string(), "--out", out("x.png")});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("manifest.json: not found"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace relslam::eval
