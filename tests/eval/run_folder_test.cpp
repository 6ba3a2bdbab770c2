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
  prepare_run_folder(dir.path(), true);
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

}  // namespace
}  // namespace relslam::eval
