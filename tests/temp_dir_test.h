// A test fixture with a fresh folder of its own: TMP/walkers_<suite>_<pid>,
// created before each test and removed after it.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

namespace walkers {

class TempDirTest : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = std::filesystem::temp_directory_path() /
            ("walkers_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->test_suite_name()) +
             "_" + std::to_string(::getpid()));
    std::filesystem::create_directories(root_);
  }
  void TearDown() override { std::filesystem::remove_all(root_); }
  // a path in the folder
  std::string Dir(const std::string& name) const { return (root_ / name).string(); }

  std::filesystem::path root_;
};

}  // namespace walkers
