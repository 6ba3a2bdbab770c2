#include "relslam/eval/io/rawlog.hpp"

#include "relslam/eval/config/input_error.hpp"
#include "relslam/eval/io/mrpt_exception_message.hpp"
#include "relslam/eval/io/range_bearing.hpp"
#include "relslam/sim/random.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>
#include <mrpt/core/Clock.h>
#include <mrpt/io/CFileOutputStream.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservationBearingRange.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>
#include <cstring>
#include <limits>

namespace relslam::eval {
namespace {

std::vector<ObservationFrame> random_frames(int count, std::vector<std::vector<int>>* ids) {
  sim::RandomSequence rng(31, sim::Stream::Field);
  std::vector<ObservationFrame> frames;
  for (int k = 0; k < count; ++k) {
    ObservationFrame f;
    f.iteration = k;
    std::vector<int> frame_ids;
    for (int i = 0; i < 5 + k; ++i) {
      f.points.emplace_back(rng.uniform(-50, 50), rng.uniform(-5, 5), rng.uniform(1, 100));
      frame_ids.push_back(100 * k + i);
    }
    frames.push_back(f);
    ids->push_back(frame_ids);
  }
  return frames;
}

RangeBearingSensor sensor() {
  RangeBearingSensor s;
  s.min_range = 1;
  s.max_range = 141.5;
  s.field_of_view_yaw_rad = M_PI / 2;
  s.field_of_view_pitch_rad = 2.7;
  return s;
}

void write_frames(const std::filesystem::path& path, bool gzip, bool with_ids, std::vector<ObservationFrame>* frames,
                  std::vector<std::vector<int>>* ids, int count = 6) {
  *frames = random_frames(count, ids);
  RawlogWriter writer(path, sensor(), gzip);
  for (std::size_t k = 0; k < frames->size(); ++k)
    writer.write((*frames)[k], with_ids ? (*ids)[k] : std::vector<int>{}, kSimulationEpoch_s + static_cast<double>(k));
  writer.close();
}

std::string error_reading(const std::filesystem::path& path) {
  try {
    read_rawlog(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

class RawlogRoundTrip : public ::testing::TestWithParam<bool> {};

TEST_P(RawlogRoundTrip, PointsIdsAndTimesComeBackToFloatPrecision) {
  test::ScratchDir dir;
  std::vector<ObservationFrame> frames;
  std::vector<std::vector<int>> ids;
  write_frames(dir / "r.rawlog", GetParam(), true, &frames, &ids);
  const Rawlog log = read_rawlog(dir / "r.rawlog");
  EXPECT_EQ(log.format, Rawlog::Format::ActionsSensoryFrames);
  EXPECT_FALSE(log.sensory_frame_first);
  EXPECT_EQ(log.records, 2 * static_cast<int>(frames.size()));
  ASSERT_EQ(log.frames.size(), frames.size());
  for (std::size_t k = 0; k < frames.size(); ++k) {
    const RawlogFrame& f = log.frames[k];
    EXPECT_EQ(f.index, static_cast<int>(k));
    EXPECT_NEAR(f.timestamp_s, kSimulationEpoch_s + k, 1e-5);
    EXPECT_FALSE(f.odometry.has_value()) << "empty actions mean no odometry";
    const ObservationFrame back = observation_frame(f);
    ASSERT_EQ(back.points.size(), frames[k].points.size());
    for (std::size_t i = 0; i < back.points.size(); ++i) {
      EXPECT_EQ(f.measurements[i].landmark_id, ids[k][i]);
      // float range, yaw and pitch: relative error a few float epsilons (1.2e-7) of the range.
      EXPECT_LT((back.points[i] - frames[k].points[i]).norm(), 1e-6 * frames[k].points[i].norm()) << k << "/" << i;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(PlainAndGzip, RawlogRoundTrip, ::testing::Bool());

// MRPT's banner, "Message:" line and call stack come down to the message; without a message
// (none, or an empty one) the first line stands in, so no failure is reported without a reason.
TEST(MrptExceptionMessage, IsTheMessageLineElseTheFirstLine) {
  EXPECT_EQ(mrpt_exception_message("==== MRPT exception ====\nMessage:  bad matrix\nCall stack:\n at f()"),
            "bad matrix");
  EXPECT_EQ(mrpt_exception_message("plain text\nsecond line"), "plain text");
  EXPECT_EQ(mrpt_exception_message("==== MRPT exception ====\nMessage:   \nCall stack:"), "==== MRPT exception ====");
}

TEST(Rawlog, UnknownAssociationWritesMinusOne) {
  test::ScratchDir dir;
  std::vector<ObservationFrame> frames;
  std::vector<std::vector<int>> ids;
  write_frames(dir / "r.rawlog", false, false, &frames, &ids);
  for (const RawlogFrame& f : read_rawlog(dir / "r.rawlog").frames)
    for (const RawlogMeasurement& m : f.measurements) EXPECT_EQ(m.landmark_id, -1);
}

TEST(Rawlog, TruncatedFileIsReportedWithTheRecord) {
  test::ScratchDir dir;
  std::vector<ObservationFrame> frames;
  std::vector<std::vector<int>> ids;
  write_frames(dir / "r.rawlog", false, true, &frames, &ids);
  const std::string bytes = test::read_file(dir / "r.rawlog");
  test::write_file(dir / "cut.rawlog", bytes.substr(0, bytes.size() - 10));
  const std::string e = error_reading(dir / "cut.rawlog");
  EXPECT_NE(e.find("cut.rawlog:12: "), std::string::npos) << e;
  EXPECT_NE(e.find("truncated: the file ends inside record 12"), std::string::npos) << e;
}

TEST(Rawlog, ForeignFilesAreRejectedWithoutCrashing) {
  test::ScratchDir dir;
  test::write_file(dir / "text.rawlog", "iteration,x,y,z\n0,1,2,3\n");
  EXPECT_NE(error_reading(dir / "text.rawlog").find("not an MRPT rawlog"), std::string::npos);
  test::write_file(dir / "empty.rawlog", "");
  EXPECT_NE(error_reading(dir / "empty.rawlog").find("empty file"), std::string::npos);
  std::string noise(4096, '\0');
  sim::RandomSequence rng(5, sim::Stream::Field);
  for (char& c : noise) c = static_cast<char>(rng.below(256));
  noise[0] = static_cast<char>(0x85);  // an MRPT-looking first byte, then garbage
  test::write_file(dir / "noise.rawlog", noise);
  EXPECT_NE(error_reading(dir / "noise.rawlog").find("noise.rawlog:1: "), std::string::npos);
  EXPECT_NE(error_reading(dir / "missing.rawlog").find("file not found"), std::string::npos);
}

TEST(Rawlog, HeaderLookingGarbageAfterTheFirstRecordIsAnError) {
  test::ScratchDir dir;
  std::vector<ObservationFrame> frames;
  std::vector<std::vector<int>> ids;
  write_frames(dir / "r.rawlog", false, true, &frames, &ids, 2);
  std::string bytes = test::read_file(dir / "r.rawlog");
  bytes += std::string(
               "\x8D"
               "CNotAClassXYZ",
               14) +
           std::string(64, '\x01');
  test::write_file(dir / "bad.rawlog", bytes);
  EXPECT_NE(error_reading(dir / "bad.rawlog").find("bad.rawlog:5: class CNotAClassXYZ is not accepted here"),
            std::string::npos)
      << error_reading(dir / "bad.rawlog");
}

// MRPT's simul-landmarks writes SF, action, SF, action...; kf-slam then drops the first SF.
TEST(Rawlog, SensoryFrameFirstFilesKeepEveryFrameAndPairOdometryWithTheNextFrame) {
  test::ScratchDir dir;
  {
    mrpt::io::CFileOutputStream out((dir / "sf_first.rawlog").string());
    auto archive = mrpt::serialization::archiveFrom(out);
    for (int k = 0; k < 3; ++k) {
      mrpt::obs::CSensoryFrame sf;
      auto obs = std::make_shared<mrpt::obs::CObservationBearingRange>();
      obs->timestamp = mrpt::Clock::fromDouble(100.0 + k);
      obs->sensedData.push_back({10.0f + k, 0.1f, 0.0f, 7, {}});
      sf.insert(obs);
      mrpt::obs::CActionCollection actions;
      mrpt::obs::CActionRobotMovement2D move;
      move.computeFromOdometry(mrpt::poses::CPose2D(1.0 + k, 0, 0), {});
      actions.insert(move);
      archive << sf << actions;
    }
  }
  const Rawlog log = read_rawlog(dir / "sf_first.rawlog");
  EXPECT_TRUE(log.sensory_frame_first);
  ASSERT_EQ(log.frames.size(), 3u);
  EXPECT_FALSE(log.frames[0].odometry.has_value());
  ASSERT_TRUE(log.frames[1].odometry.has_value());
  EXPECT_NEAR(log.frames[1].odometry->translation.x(), 1.0, 1e-9) << "the action after frame 0";
  EXPECT_NEAR(log.frames[2].odometry->translation.x(), 2.0, 1e-9);
  EXPECT_NEAR(log.frames[2].measurements[0].range, 12.0f, 1e-6);
}

TEST(Rawlog, ObservationOnlyFilesAreReadWithOdometryIncrements) {
  test::ScratchDir dir;
  {
    mrpt::io::CFileOutputStream out((dir / "obs.rawlog").string());
    auto archive = mrpt::serialization::archiveFrom(out);
    for (int k = 0; k < 3; ++k) {
      mrpt::obs::CObservationOdometry odo;
      odo.odometry = mrpt::poses::CPose2D(2.0 * k, 0, 0);
      archive << odo;
      mrpt::obs::CObservationBearingRange obs;
      obs.sensedData.push_back({5.0f, 0.0f, 0.0f, -1, {}});
      archive << obs;
    }
  }
  const Rawlog log = read_rawlog(dir / "obs.rawlog");
  EXPECT_EQ(log.format, Rawlog::Format::ObservationsOnly);
  ASSERT_EQ(log.frames.size(), 3u);
  EXPECT_FALSE(log.frames[0].odometry.has_value());
  EXPECT_NEAR(log.frames[2].odometry->translation.x(), 2.0, 1e-9);
}

TEST(Rawlog, SensorPoseOnTheRobotIsAppliedToThePoints) {
  test::ScratchDir dir;
  {
    mrpt::io::CFileOutputStream out((dir / "offset.rawlog").string());
    auto archive = mrpt::serialization::archiveFrom(out);
    mrpt::obs::CObservationBearingRange obs;
    obs.sensorLocationOnRobot = mrpt::poses::CPose3D(1.0, 0.5, 0.2, 0, 0, 0);  // x fwd, y left, z up
    obs.sensedData.push_back({10.0f, 0.0f, 0.0f, -1, {}});                     // 10 ahead of the sensor
    archive << obs;
  }
  const ObservationFrame f = observation_frame(read_rawlog(dir / "offset.rawlog").frames.at(0));
  // Our robot frame: +x left, +y up, +z forward.
  EXPECT_LT((f.points.at(0) - Eigen::Vector3d(0.5, 0.2, 11.0)).norm(), 1e-6);
}

TEST(Rawlog, FileWithoutBearingRangeObservationsIsAnError) {
  test::ScratchDir dir;
  {
    mrpt::io::CFileOutputStream out((dir / "odo.rawlog").string());
    auto archive = mrpt::serialization::archiveFrom(out);
    mrpt::obs::CObservationOdometry odo;
    archive << odo;
  }
  EXPECT_NE(error_reading(dir / "odo.rawlog").find("no CObservationBearingRange"), std::string::npos);
}

}  // namespace
}  // namespace relslam::eval

namespace relslam::eval {
namespace {

TEST(Rawlog, NonFiniteMeasurementsAreRejectedWithRecordAndIndex) {
  test::ScratchDir dir;
  {
    mrpt::io::CFileOutputStream out((dir / "nan.rawlog").string());
    auto archive = mrpt::serialization::archiveFrom(out);
    mrpt::obs::CActionCollection actions;
    mrpt::obs::CSensoryFrame sf;
    auto obs = std::make_shared<mrpt::obs::CObservationBearingRange>();
    obs->sensedData.push_back({5.0f, 0.0f, 0.0f, 1, {}});
    obs->sensedData.push_back({std::numeric_limits<float>::quiet_NaN(), 0.0f, 0.0f, 2, {}});
    sf.insert(obs);
    archive << actions << sf;
  }
  const std::string e = error_reading(dir / "nan.rawlog");
  EXPECT_NE(e.find("nan.rawlog:2: sensedData[1]: range/yaw/pitch must be finite"), std::string::npos) << e;
}

}  // namespace
}  // namespace relslam::eval

// Our own bounds on MRPT's framing: the mutations the fuzzer found, on a file we write.
namespace relslam::eval {
namespace {

// A one-frame rawlog as bytes: action collection (record 1), then a sensory frame (record 2)
// with one bearing-range observation of `points` measurements.
std::string one_frame_rawlog(const test::ScratchDir& dir, int points = 3) {
  ObservationFrame frame;
  for (int i = 0; i < points; ++i) frame.points.emplace_back(1.0 + i, 0.5, 10.0);
  RawlogWriter writer(dir / "one.rawlog", sensor(), false);
  writer.write(frame, {}, kSimulationEpoch_s);
  writer.close();
  return test::read_file(dir / "one.rawlog");
}

std::string error_reading_bytes(const std::string& bytes) {
  try {
    read_rawlog_bytes(bytes, "m.rawlog");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

// The offset of the measurement count: right before the first measurement's four fields.
std::size_t count_offset(const std::string& bytes, int points) {
  // The label "RELSLAM_SIM" follows the measurements (4-byte length, then the text).
  const std::size_t label = bytes.find("RELSLAM_SIM");
  return label - 4 - 16 * static_cast<std::size_t>(points) - 4;
}

TEST(RawlogBounds, MemoryAndFileReadersAgree) {
  test::ScratchDir dir;
  const std::string bytes = one_frame_rawlog(dir);
  const Rawlog from_file = read_rawlog(dir / "one.rawlog");
  const Rawlog from_memory = read_rawlog_bytes(bytes, "m.rawlog");
  ASSERT_EQ(from_memory.frames.size(), 1u);
  ASSERT_EQ(from_memory.frames[0].measurements.size(), from_file.frames[0].measurements.size());
  EXPECT_EQ(from_memory.frames[0].measurements[2].range, from_file.frames[0].measurements[2].range);
}

TEST(RawlogBounds, CountBeyondWhatARecordMayHoldIsRefusedBeforeAllocating) {
  test::ScratchDir dir;
  std::string bytes = one_frame_rawlog(dir);
  const std::uint32_t huge = 0xF0000000u;
  std::memcpy(bytes.data() + count_offset(bytes, 3), &huge, 4);
  const std::string e = error_reading_bytes(bytes);
  EXPECT_NE(e.find("m.rawlog:2: CSensoryFrame.observations[0].CObservationBearingRange.sensedData: count 4026531840"),
            std::string::npos)
      << e;
}

TEST(RawlogBounds, CountTheFileDoesNotHoldIsATruncation) {
  test::ScratchDir dir;
  std::string bytes = one_frame_rawlog(dir);
  const std::uint32_t more = 1000000;  // 16 MB of measurements in a file of a few hundred bytes
  std::memcpy(bytes.data() + count_offset(bytes, 3), &more, 4);
  const std::string e = error_reading_bytes(bytes);
  EXPECT_NE(e.find("m.rawlog:2: "), std::string::npos) << e;
  EXPECT_NE(e.find("truncated: the file ends inside record 2"), std::string::npos) << e;
}

TEST(RawlogBounds, FlagOtherThanZeroOrOneIsRefused) {
  test::ScratchDir dir;
  std::string bytes = one_frame_rawlog(dir);
  // validCovariances: the byte before the three sensor std floats, which come before the count.
  bytes[count_offset(bytes, 3) - 13] = 2;
  const std::string e = error_reading_bytes(bytes);
  EXPECT_NE(e.find("CObservationBearingRange.validCovariances: a flag must be 0 or 1, got 2"), std::string::npos) << e;
}

TEST(RawlogBounds, ClassesOutsideTheAcceptedListAreNamed) {
  mrpt::io::CMemoryStream memory;
  auto archive = mrpt::serialization::archiveFrom(memory);
  archive << mrpt::poses::CPose2D(1, 2, 3);
  const std::string bytes(reinterpret_cast<const char*>(memory.getRawBufferData()), memory.getTotalBytesCount());
  const std::string e = error_reading_bytes(bytes);
  EXPECT_NE(e.find("m.rawlog:1: not an MRPT rawlog (class mrpt::poses::CPose2D is not accepted here (accepted: "
                   "CActionCollection, CSensoryFrame, CObservationBearingRange, CObservation2DRangeScan, "
                   "CObservationOdometry))"),
            std::string::npos)
      << e;
}

TEST(RawlogBounds, NonFiniteSensorPoseIsRefusedWithTheField) {
  test::ScratchDir dir;
  {
    mrpt::io::CFileOutputStream out((dir / "pose.rawlog").string());
    auto archive = mrpt::serialization::archiveFrom(out);
    mrpt::obs::CObservationBearingRange obs;
    obs.sensorLocationOnRobot = mrpt::poses::CPose3D(std::numeric_limits<double>::quiet_NaN(), 0, 0, 0, 0, 0);
    obs.sensedData.push_back({10.0f, 0.0f, 0.0f, -1, {}});
    archive << obs;
  }
  const std::string e = error_reading(dir / "pose.rawlog");
  EXPECT_NE(e.find("pose.rawlog:1: sensorLocationOnRobot: pose must be finite"), std::string::npos) << e;
}

TEST(RawlogBounds, ThrunModelWithAbsurdParticleCountIsRefused) {
  test::ScratchDir dir;
  {
    mrpt::io::CFileOutputStream out((dir / "thrun.rawlog").string());
    auto archive = mrpt::serialization::archiveFrom(out);
    mrpt::obs::CActionCollection actions;
    mrpt::obs::CActionRobotMovement2D move;
    mrpt::obs::CActionRobotMovement2D::TMotionModelOptions model;
    model.modelSelection = mrpt::obs::CActionRobotMovement2D::mmThrun;
    model.thrunModel.nParticlesCount = 300;
    move.computeFromOdometry(mrpt::poses::CPose2D(1, 0, 0), model);
    move.motionModelConfiguration.thrunModel.nParticlesCount = 50000000;  // as a mutated file says
    actions.insert(move);
    archive << actions;
  }
  const std::string e = error_reading(dir / "thrun.rawlog");
  EXPECT_NE(e.find("thrun.rawlog:1: CActionCollection.actions[0].CActionRobotMovement2D.nParticlesCount: must be in "
                   "[1, 100000] for the Thrun model, got 50000000"),
            std::string::npos)
      << e;
}

// MRPT's demo logs (older class versions, names without namespaces) still read, where installed.
TEST(RawlogBounds, MrptDemoLogsPassTheBounds) {
  int read = 0;
  for (const char* name : {"kf-slam_demo.rawlog", "kf-slam_6D_demo.rawlog", "kf-slam_6D_demo_DA.rawlog",
                           "kf-slam_6D_demo_noncentered.rawlog"}) {
    const std::filesystem::path file = std::filesystem::path("/usr/share/mrpt/datasets") / name;
    if (!std::filesystem::exists(file)) continue;
    EXPECT_GT(read_rawlog(file).frames.size(), 10u) << name;
    ++read;
  }
  if (read == 0) GTEST_SKIP() << "MRPT's demo logs not installed (apt-get install mrpt-common)";
}

}  // namespace
}  // namespace relslam::eval

// Sensor fields are checked for sense, not only finiteness: a negative field of view,
// a maximum range below the minimum or readings of 3e38 ran the EKF for minutes, a sensor 1e300
// away from the robot gave NaN, and two finite odometry readings differed by infinity.
namespace relslam::eval {
namespace {

// An observation-only rawlog of one bearing-range observation, `change` applied to it first.
template <class Change>
std::string error_with_observation(const test::ScratchDir& dir, Change change) {
  {
    mrpt::io::CFileOutputStream out((dir / "s.rawlog").string());
    auto archive = mrpt::serialization::archiveFrom(out);
    mrpt::obs::CObservationBearingRange obs;
    obs.minSensorDistance = 0.5f;
    obs.maxSensorDistance = 20.0f;
    obs.sensedData.push_back({10.0f, 0.1f, 0.0f, -1, {}});
    change(obs);
    archive << obs;
  }
  return error_reading(dir / "s.rawlog");
}

TEST(RawlogSense, SensorFieldsOutOfTheirRangesAreRefusedWithTheField) {
  test::ScratchDir dir;
  using Obs = mrpt::obs::CObservationBearingRange;
  EXPECT_EQ(error_with_observation(dir, [](Obs&) {}), "(no error)");
  EXPECT_EQ(error_with_observation(dir, [](Obs& o) { o.fieldOfView_yaw = -1.0f; }),
            (dir / "s.rawlog").string() + ":1: fieldOfView_yaw: must be in (0, 2 pi], got -1");
  EXPECT_EQ(error_with_observation(dir, [](Obs& o) { o.maxSensorDistance = 0.25f; }),
            (dir / "s.rawlog").string() +
                ":1: maxSensorDistance: must be above minSensorDistance (0.5), or 0 with it for no range given, got "
                "0.25");
  EXPECT_NE(error_with_observation(dir, [](Obs& o) { o.sensedData[0].range = 3e38f; })
                .find("s.rawlog:1: sensedData[0]: range 3.0000000"),
            std::string::npos);
  EXPECT_NE(error_with_observation(dir, [](Obs& o) { o.sensedData[0].range = 3e38f; })
                .find("beyond the observation's maxSensorDistance 20 (at most 22"),
            std::string::npos);
  EXPECT_EQ(error_with_observation(dir, [](Obs& o) { o.sensedData[0].range = 21.5f; }), "(no error)");
  EXPECT_EQ(
      error_with_observation(dir, [](Obs& o) { o.sensorLocationOnRobot = mrpt::poses::CPose3D(1e300, 0, 0, 0, 0, 0); }),
      (dir / "s.rawlog").string() +
          ":1: sensorLocationOnRobot: each coordinate must be within +-1000 m, got (1e+300, 0, 0)");
  // MRPT's defaults (no range given) stay readable.
  EXPECT_EQ(error_with_observation(dir,
                                   [](Obs& o) {
                                     o.minSensorDistance = 0;
                                     o.maxSensorDistance = 0;
                                   }),
            "(no error)");
}

TEST(RawlogSense, OdometryIncrementsOutOfRangeAreRefused) {
  test::ScratchDir dir;
  const auto write = [&](double x0, double x1) {
    mrpt::io::CFileOutputStream out((dir / "odo.rawlog").string());
    auto archive = mrpt::serialization::archiveFrom(out);
    for (const double x : {x0, x1}) {
      mrpt::obs::CObservationOdometry odo;
      odo.odometry = mrpt::poses::CPose2D(x, 0, 0);
      archive << odo;
      mrpt::obs::CObservationBearingRange obs;
      obs.sensedData.push_back({5.0f, 0.0f, 0.0f, -1, {}});
      archive << obs;
    }
  };
  write(1e308, -1e308);  // each finite; their difference is not
  EXPECT_NE(error_reading(dir / "odo.rawlog")
                .find("odo.rawlog:1: CObservationOdometry.odometry: each coordinate must "
                      "be within +-1e+09 m, got (1e+308, 0, 0)"),
            std::string::npos)
      << error_reading(dir / "odo.rawlog");
  write(0, 2e4);
  EXPECT_NE(error_reading(dir / "odo.rawlog")
                .find("odo.rawlog:3: CObservationOdometry.odometry (since the last reading): each coordinate must be "
                      "within +-10000 m, got (20000, 0, 0)"),
            std::string::npos)
      << error_reading(dir / "odo.rawlog");
}

// A gzip file of repeated readings compresses a thousandfold: its decoded size is bounded by a
// multiple of the file's size (a 995 KB file of eight records took 1.15 GB).
TEST(RawlogSense, GzipFileDecodingFarBeyondItsSizeIsRefused) {
  test::ScratchDir dir;
  ObservationFrame frame;
  frame.points.assign(900'000, Eigen::Vector3d(1.0, 0.5, 10.0));  // 14.4 MB a record
  {
    RawlogWriter writer(dir / "bomb.rawlog.gz", sensor(), true);
    for (int k = 0; k < 5; ++k) writer.write(frame, {}, kSimulationEpoch_s + k);
    writer.close();
  }
  ASSERT_LT(std::filesystem::file_size(dir / "bomb.rawlog.gz"), kMinRawlogBudgetBytes / kMaxRawlogExpansion);
  const std::string e = error_reading(dir / "bomb.rawlog.gz");
  EXPECT_NE(e.find("bomb.rawlog.gz:10: the file decodes to more than 67108864 bytes"), std::string::npos) << e;
}

}  // namespace
}  // namespace relslam::eval
