// relslam render: the replayed state drawn where the axes say, pictures of the asked size, a
// video with one frame per step, and bad requests refused with the option named; for point runs
// and for planar ones.
#include "relslam/eval/io/map_render.hpp"
#include "relslam/eval/io/planar_render.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/videoio.hpp>

#include <filesystem>

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

// ---- planar runs (thesis Fig. 67) ----------------------------

const cv::Vec3b kWall(0, 215, 255);        // true walls, yellow
const cv::Vec3b kMappedPlane(200, 70, 0);  // mapped planes, blue
const cv::Vec3b kReading(0, 0, 230);       // current readings, red

TEST(PlanarRender, TopViewPutsXRightAndZUp) {
  PlanarScene scene;
  scene.walls = {{Eigen::Vector2d(10, -5), Eigen::Vector2d(10, 5)},   // across x = 10
                 {Eigen::Vector2d(-5, 20), Eigen::Vector2d(5, 20)}};  // across z = 20
  RenderOptions options;
  options.width = 400;
  options.height = 400;
  const cv::Mat image = render_map(scene, {0, 0, 100}, options);  // 4 pixels per unit, centre (200, 200)
  ASSERT_EQ(image.cols, 400);
  EXPECT_EQ(image.at<cv::Vec3b>(200, 200 + 40), kWall);  // x = 10 -> 40 px right of centre
  EXPECT_EQ(image.at<cv::Vec3b>(200 - 80, 200), kWall);  // z = 20 -> 80 px above centre
  // Nothing blue above the legend (which holds a swatch of each colour).
  EXPECT_EQ(count_colour(image(cv::Rect(0, 0, 400, 280)), kMappedPlane), 0);
}

TEST(PlanarRender, GroupsJoinTheirPlanesAndReadingsLieOnTop) {
  PlanarScene scene;
  const PlaneObject wall{Eigen::Vector2d(-10, 10), Eigen::Vector2d(10, 10)};
  scene.walls = {wall};
  scene.mapped = {wall};
  scene.readings = {wall};
  scene.groups = {{0, Eigen::Vector2d(0, -10), {wall.midpoint()}}};
  RenderOptions options;
  options.width = 400;
  options.height = 400;
  const cv::Mat image = render_map(scene, {0, 0, 100}, options);
  // The reading is drawn over the mapped plane over the wall, each narrower than the last.
  EXPECT_EQ(image.at<cv::Vec3b>(200 - 40, 200 + 20), kReading);
  EXPECT_GT(count_colour(image, kMappedPlane), 0);
  EXPECT_GT(count_colour(image, kWall), 0);
  // The group's line runs from its label at z = -10 up to the plane's midpoint.
  EXPECT_NE(image.at<cv::Vec3b>(200, 200), cv::Vec3b(255, 255, 255));
}

class PlanarRenderCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new test::ScratchDir;
    const auto r = test::run_relslam({"run", test::source_path("scenarios/p-hallway.json").string(), "--set",
                                      "planar.iterations=200", "--out", (*dir_ / "run").string(), "-q"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  static void TearDownTestSuite() { delete dir_; }
  static std::string run_dir() { return (*dir_ / "run").string(); }
  static std::string out(const std::string& name) { return (*dir_ / name).string(); }
  static test::ScratchDir* dir_;
};
test::ScratchDir* PlanarRenderCli::dir_ = nullptr;

TEST_F(PlanarRenderCli, DrawsWallsAndMappedPlanesAtTheAskedSize) {
  const auto r = test::run_relslam(
      {"render", run_dir(), "--iteration", "150", "--width", "800", "--height", "400", "--out", out("plan.png")});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // The replay reached the pose the run recorded: no warning; the run's plane algorithm was drawn.
  EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("relative_plane, iteration 150"), std::string::npos) << r.out;
  const cv::Mat image = cv::imread(out("plan.png"));
  ASSERT_FALSE(image.empty());
  EXPECT_EQ(image.cols, 800);
  EXPECT_EQ(image.rows, 400);
  // Left of the legend, which holds a swatch of each colour.
  const cv::Mat drawing = image(cv::Rect(0, 0, image.cols - 300, image.rows));
  EXPECT_GT(count_colour(drawing, kWall), 100);
  EXPECT_GT(count_colour(drawing, kMappedPlane), 100);
  EXPECT_GT(count_colour(drawing, kReading), 20);
  // Deterministic: the same request gives the same bytes; a close-up and a centred view work too.
  ASSERT_EQ(test::run_relslam({"render", run_dir(), "--iteration", "150", "--width", "800", "--height", "400", "--out",
                               out("again.png"), "-q"})
                .exit_code,
            0);
  EXPECT_EQ(test::read_file(out("plan.png")), test::read_file(out("again.png")));
  EXPECT_EQ(test::run_relslam({"render", run_dir(), "--fit", "robot", "--out", out("close.png"), "-q"}).exit_code, 0);
  EXPECT_EQ(test::run_relslam({"render", run_dir(), "--center", "10,0", "--span", "20", "--labels", "on", "--out",
                               out("centred.png"), "-q"})
                .exit_code,
            0);
}

TEST_F(PlanarRenderCli, AVideoHasAFramePerStep) {
  const auto r = test::run_relslam(
      {"render", run_dir(), "--video", out("plan.mp4"), "--every", "20", "--width", "320", "--height", "240", "-q"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  cv::VideoCapture video(out("plan.mp4"));
  ASSERT_TRUE(video.isOpened());
  EXPECT_EQ(video.get(cv::CAP_PROP_FRAME_COUNT), 10);  // iterations 0, 20, ..., 180
  EXPECT_EQ(video.get(cv::CAP_PROP_FRAME_WIDTH), 320);
}

TEST_F(PlanarRenderCli, FindsTheMapByTheRecordedFileWhenItsNameIsGone) {
  // A run folder whose scenario names a map this checkout does not have (renamed since):
  // the manifest's planar_simulation.map_file still leads to it.
  test::ScratchDir moved;
  std::filesystem::copy(run_dir(), moved / "run", std::filesystem::copy_options::recursive);
  const std::filesystem::path file = moved / "run" / "manifest.json";
  nlohmann::json manifest = nlohmann::json::parse(test::read_file(file));
  ASSERT_TRUE(manifest["planar_simulation"].contains("map_file")) << manifest.dump(2);
  manifest["scenario"]["planar"]["map"] = "no_such_map";
  test::write_file(file, manifest.dump(2));
  const auto r = test::run_relslam(
      {"render", (moved / "run").string(), "--iteration", "100", "--out", (moved / "x.png").string(), "-q"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
  // Without the recorded file, the error names the missing map.
  manifest["planar_simulation"].erase("map_file");
  test::write_file(file, manifest.dump(2));
  const auto bad = test::run_relslam({"render", (moved / "run").string(), "--out", (moved / "x.png").string()});
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("no_such_map"), std::string::npos) << bad.err;
}

TEST_F(PlanarRenderCli, BadRequestsNameTheOption) {
  struct Case {
    std::vector<std::string> args;
    std::string expected;
  };
  for (const Case& c : std::vector<Case>{
           {{"--iteration", "200", "--out", out("x.png")}, "--iteration: the run has iterations 0..199, got 200"},
           {{"--algorithm", "relative_point", "--out", out("x.png")}, "--algorithm: a planar run draws a plane"},
           {{"--view", "side", "--out", out("x.png")}, "--view: a planar run is drawn from the top only"},
       }) {
    std::vector<std::string> args = {"render", run_dir()};
    args.insert(args.end(), c.args.begin(), c.args.end());
    const auto r = test::run_relslam(args);
    EXPECT_EQ(r.exit_code, 2) << c.expected;
    EXPECT_NE(r.err.find(c.expected), std::string::npos) << r.err;
  }
}

}  // namespace
}  // namespace relslam::eval
