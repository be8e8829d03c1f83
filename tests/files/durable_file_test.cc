#include "files/durable_file.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <gtest/gtest.h>

#include "tests/temp_dir_test.h"

namespace walkers {
namespace {
namespace fs = std::filesystem;

std::string Contents(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

using DurableFileTest = TempDirTest;

TEST_F(DurableFileTest, AnAtomicWriteReplacesTheFileWholeAndLeavesNoTemporary) {
  const std::string path = Dir("a.json");
  WriteFileAtomically(path, "first\n");
  WriteFileAtomically(path, "second, longer\n");
  EXPECT_EQ(Contents(path), "second, longer\n");
  EXPECT_FALSE(fs::exists(TemporaryPathFor(path)));
  EXPECT_EQ(TemporaryPathFor(path), path + ".tmp." + std::to_string(::getpid()));
}

TEST_F(DurableFileTest, AnAtomicWriteIntoAMissingFolderFailsNamingTheFile) {
  try {
    WriteFileAtomically(Dir("absent/a.json"), "x");
    FAIL() << "wrote into a folder that does not exist";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("absent/a.json.tmp."), std::string::npos) << e.what();
  }
}

TEST_F(DurableFileTest, AWriterLeavesTheOldFileUntilItCommits) {
  const std::string path = Dir("t.csv");
  WriteFileAtomically(path, "old\n");
  {
    AtomicFileWriter writer(path, "the trajectory file");
    writer.stream() << "new\n";
    EXPECT_EQ(Contents(path), "old\n");
    EXPECT_TRUE(fs::exists(TemporaryPathFor(path)));
  }  // abandoned: the old file stays, the temporary goes
  EXPECT_EQ(Contents(path), "old\n");
  EXPECT_FALSE(fs::exists(TemporaryPathFor(path)));
  AtomicFileWriter writer(path, "the trajectory file");
  writer.stream() << "new\n";
  writer.Commit();
  EXPECT_EQ(Contents(path), "new\n");
  EXPECT_FALSE(fs::exists(TemporaryPathFor(path)));
}

TEST_F(DurableFileTest, AppendsReturnTheSizeAndTruncationCutsBackToIt) {
  const std::string path = Dir("rows.csv");
  EXPECT_EQ(AppendDurably(path, "header\n"), 7u);
  const std::uint64_t checkpoint = AppendDurably(path, "row 1\n");
  EXPECT_EQ(checkpoint, 13u);
  const std::uint64_t size = AppendDurably(path, "row 2, after the checkpoint\n");
  EXPECT_EQ(size, FileSize(path));
  EXPECT_EQ(size, checkpoint + 28);
  TruncateFile(path, checkpoint);
  EXPECT_EQ(Contents(path), "header\nrow 1\n");
  EXPECT_THROW(FileSize(Dir("absent.csv")), std::runtime_error);
}

TEST_F(DurableFileTest, OnlyOtherProcessesTemporariesAreStale) {
  const std::string mine = TemporaryPathFor(Dir("a.json"));
  const std::string killed = Dir("b.json.tmp.999999999");
  const std::string not_one = Dir("c.tmp.json");
  for (const std::string& path : {mine, killed, not_one}) std::ofstream(path) << "x";
  RemoveStaleTemporaries(root_.string());
  EXPECT_TRUE(fs::exists(mine));
  EXPECT_FALSE(fs::exists(killed));
  EXPECT_TRUE(fs::exists(not_one));
}

}  // namespace
}  // namespace walkers
