#include "files/results_folder.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include <gtest/gtest.h>

#include "tests/temp_dir_test.h"

namespace walkers {
namespace {
namespace fs = std::filesystem;

class ResultsFolderTest : public TempDirTest {
 protected:
  // results of one file, "result.txt", whose first checkpoint is "checkpoint.txt"
  ResultsFolder Open(const std::string& dir, StartMode mode) {
    return ResultsFolder(dir, "run", mode, (fs::path(dir) / "checkpoint.txt").string(), [dir] {
      FolderContents held{{"result.txt", "checkpoint.txt"}, "", false};
      for (const std::string& name : held.names) held.any = held.any || fs::exists(fs::path(dir) / name);
      return held;
    });
  }
  static void Write(const fs::path& path, const std::string& text) { std::ofstream(path) << text; }
  static std::string Read(const fs::path& path) {
    std::ifstream in(path);
    return std::string(std::istreambuf_iterator<char>(in), {});
  }
  // the message of the std::runtime_error `f` throws, or "" if it throws none
  template <typename F>
  static std::string Error(const F& f) {
    try {
      f();
    } catch (const std::runtime_error& e) {
      return e.what();
    }
    return "";
  }
};

TEST_F(ResultsFolderTest, ANewFolderIsCreatedAndOneHoldingResultsRefused) {
  const std::string dir = Dir("a");
  { ResultsFolder folder = Open(dir, StartMode::kNew); }
  EXPECT_TRUE(fs::is_directory(dir));
  Write(fs::path(dir) / "result.txt", "old");
  EXPECT_EQ(Error([&] { Open(dir, StartMode::kNew); }),
            dir + ": holds a run already; pass --resume to continue it or --force to replace it");
}

TEST_F(ResultsFolderTest, ResumingNeedsTheFolderAndNeverCreatesIt) {
  EXPECT_EQ(Error([&] { Open(Dir("absent"), StartMode::kResume); }),
            Dir("absent") + ": no run to resume (no such directory)");
  EXPECT_FALSE(fs::exists(Dir("absent")));
}

TEST_F(ResultsFolderTest, OneWriterAtATimeAndTheRefusalNamesTheHolder) {
  const std::string dir = Dir("a");
  ResultsFolder first = Open(dir, StartMode::kNew);
  const std::string error = Error([&] { Open(dir, StartMode::kResume); });
  EXPECT_NE(error.find("(pid " + std::to_string(::getpid()) + ") is writing this run"), std::string::npos) << error;
}

TEST_F(ResultsFolderTest, ForceSetsTheOldResultsAsideUntilTheFirstCheckpoint) {
  const std::string dir = Dir("a");
  fs::create_directories(dir);
  Write(fs::path(dir) / "result.txt", "old");
  Write(fs::path(dir) / "notes.txt", "not the run's");
  {
    ResultsFolder forced = Open(dir, StartMode::kForce);
    EXPECT_EQ(Read(fs::path(dir) / "replaced" / "result.txt"), "old");
    Write(fs::path(dir) / "result.txt", "new, abandoned");
  }  // abandoned before its first checkpoint: the old run is back
  EXPECT_EQ(Read(fs::path(dir) / "result.txt"), "old");
  EXPECT_FALSE(fs::exists(fs::path(dir) / "replaced"));
  {
    ResultsFolder forced = Open(dir, StartMode::kForce);
    Write(fs::path(dir) / "result.txt", "new");
    forced.DiscardReplaced();
    forced.DiscardReplaced();  // a second time does nothing
    EXPECT_FALSE(fs::exists(fs::path(dir) / "replaced"));
  }
  EXPECT_EQ(Read(fs::path(dir) / "result.txt"), "new");
  EXPECT_EQ(Read(fs::path(dir) / "notes.txt"), "not the run's");
}

TEST_F(ResultsFolderTest, AForceStoppedBeforeItsFirstCheckpointIsNamedUntilDecided) {
  const std::string dir = Dir("a");
  fs::create_directories(fs::path(dir) / "replaced");
  Write(fs::path(dir) / "replaced" / "result.txt", "old");
  EXPECT_NE(Error([&] { Open(dir, StartMode::kResume); }).find("a --force was stopped"), std::string::npos);
  EXPECT_NE(Error([&] { Open(dir, StartMode::kNew); }).find("holds a run already (" + dir + "/replaced)"),
            std::string::npos);
  // the new results reached their first checkpoint: the old ones go
  Write(fs::path(dir) / "checkpoint.txt", "1");
  { ResultsFolder resumed = Open(dir, StartMode::kResume); }
  EXPECT_FALSE(fs::exists(fs::path(dir) / "replaced"));
}

TEST_F(ResultsFolderTest, AProcessStoppedWhileSettingAsideIsUndoneFirst) {
  const std::string dir = Dir("a");
  fs::create_directories(fs::path(dir) / "replaced.partial");
  Write(fs::path(dir) / "replaced.partial" / "result.txt", "old");
  { ResultsFolder resumed = Open(dir, StartMode::kResume); }
  EXPECT_EQ(Read(fs::path(dir) / "result.txt"), "old");
  EXPECT_FALSE(fs::exists(fs::path(dir) / "replaced.partial"));
}

}  // namespace
}  // namespace walkers
