#include "relslam/eval/io/run_folder.hpp"

#include "relslam/eval/config/input_error.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

namespace relslam::eval {
namespace {

TEST(RunFolder, CreatesMissingFolders) {
  test::ScratchDir dir;
  prepare_run_folder(dir / "a/b", false);
  EXPECT_TRUE(std::filesystem::is_directory(dir / "a/b"));
}

TEST(RunFolder, RefusesANonEmptyFolderWithoutForce) {
  test::ScratchDir dir;
  test::write_file(dir / "x.txt", "keep me");
  EXPECT_THROW(prepare_run_folder(dir.path(), false), InputError);
  EXPECT_TRUE(std::filesystem::exists(dir / "x.txt"));
}

TEST(RunFolder, ForceReplacesAnEarlierRunOnly) {
  test::ScratchDir dir;
  test::write_file(dir / "x.txt", "keep me");
  EXPECT_THROW(prepare_run_folder(dir.path(), true), InputError) << "no manifest.json: not a run folder";
  EXPECT_TRUE(std::filesystem::exists(dir / "x.txt"));
  test::write_file(dir / "manifest.json", "{}");
  EXPECT_THROW(prepare_run_folder(dir.path(), true), InputError) << "a manifest, but not relslam's";
  EXPECT_TRUE(std::filesystem::exists(dir / "x.txt"));
  test::write_file(dir / "manifest.json", R"({"relslam_version": "0.1", "status": "ok"})");
  prepare_run_folder(dir.path(), true);
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

TEST(RunFolder, ForceReplacesAKilledRunStillMarkedRunning) {
  test::ScratchDir dir;
  std::filesystem::create_directories(dir / "relative_point");
  test::write_file(dir / "relative_point" / "iterations.csv", "iteration\n1\n");
  test::write_file(dir / "manifest.json", R"({"relslam_version": "0.1", "status": "running"})");
  prepare_run_folder(dir.path(), true);
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

TEST(RunFolder, ManifestRecordsTheStatusAndLeavesNoPartialFile) {
  test::ScratchDir dir;
  write_manifest(dir.path(), Scenario{}, {"run", {"relslam", "run"}, "", {}}, {}, kRunStatusRunning);
  EXPECT_EQ(nlohmann::json::parse(test::read_file(dir / "manifest.json"))["status"], "running");
  write_manifest(dir.path(), Scenario{}, {"run", {"relslam", "run"}, "", {}}, {}, failed_status("disk full"));
  EXPECT_EQ(nlohmann::json::parse(test::read_file(dir / "manifest.json"))["status"], "failed: disk full");
  EXPECT_FALSE(std::filesystem::exists(dir / "manifest.json.partial"));
}

}  // namespace
}  // namespace relslam::eval
