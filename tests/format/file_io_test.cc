// Atomic saves: a process killed at any moment while saving leaves either the
// old complete file or the new complete file; a save that fails (file size
// limit as a stand-in for a full disk, a missing folder) leaves the old file.
#include "format/file_io.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <random>
#include <string>

#include "tests/testing/test_support.h"

namespace linemap {
namespace {

using testing::MakeTempDir;
using testing::ReadFile;
using testing::WriteFile;

// A file of `size` bytes all equal to `version`, so a torn write shows.
std::string Version(char version, std::size_t size) { return std::string(size, version); }

bool IsWholeVersion(const std::string& data, std::size_t size) {
  if (data.size() != size) return false;
  return data.find_first_not_of(data[0]) == std::string::npos;
}

TEST(FileIoTest, ReadsBackWhatWasWritten) {
  const std::string dir = MakeTempDir("fio");
  ASSERT_TRUE(WriteFileAtomic(dir + "/a.bin", "hello").ok());
  StatusOr<std::vector<std::uint8_t>> bytes = ReadFileBytes(dir + "/a.bin", 100);
  ASSERT_TRUE(bytes.ok());
  EXPECT_EQ(std::string(bytes->begin(), bytes->end()), "hello");
  EXPECT_EQ(testing::ListDir(dir), std::vector<std::string>{"a.bin"});
}

TEST(FileIoTest, UnsyncedWriteReplacesTheFileWhole) {
  const std::string dir = MakeTempDir("fio");
  ASSERT_TRUE(WriteFileAtomic(dir + "/a.bin", "old contents").ok());
  ASSERT_TRUE(WriteFileAtomic(dir + "/a.bin", "new", Durability::kUnsynced).ok());
  StatusOr<std::vector<std::uint8_t>> bytes = ReadFileBytes(dir + "/a.bin", 100);
  ASSERT_TRUE(bytes.ok());
  EXPECT_EQ(std::string(bytes->begin(), bytes->end()), "new");
  EXPECT_EQ(testing::ListDir(dir), std::vector<std::string>{"a.bin"});
}

TEST(FileIoTest, ReadErrorsNameTheFile) {
  const std::string dir = MakeTempDir("fio");
  WriteFile(dir + "/big.bin", std::string(101, 'x'));
  EXPECT_EQ(ReadFileBytes(dir + "/missing.bin", 100).status().code(), StatusCode::kNotFound);
  StatusOr<std::vector<std::uint8_t>> big = ReadFileBytes(dir + "/big.bin", 100);
  EXPECT_EQ(big.status().code(), StatusCode::kResourceExhausted);
  EXPECT_NE(big.status().message().find("big.bin"), std::string::npos);
  EXPECT_EQ(ReadFileBytes(dir, 100).status().code(), StatusCode::kInvalidArgument);
}

TEST(FileIoTest, WriteOntoADirectoryFails) {
  const std::string dir = MakeTempDir("fio");
  EXPECT_EQ(WriteFileAtomic(dir, "x").code(), StatusCode::kInvalidArgument);
}

TEST(FileIoTest, FailedWriteLeavesTheOldFile) {
  const std::string dir = MakeTempDir("fio");
  const std::string target = dir + "/map.lmap";
  WriteFile(target, "old complete file");
  // A child with a 4 KiB file-size limit: writing 1 MiB fails as on a full disk.
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    ::signal(SIGXFSZ, SIG_IGN);
    struct rlimit limit = {4096, 4096};
    ::setrlimit(RLIMIT_FSIZE, &limit);
    const Status status = WriteFileAtomic(target, Version('n', 1 << 20));
    _exit(status.ok() ? 0 : (status.code() == StatusCode::kIoError ? 3 : 4));
  }
  int wstatus = 0;
  ::waitpid(pid, &wstatus, 0);
  ASSERT_TRUE(WIFEXITED(wstatus));
  EXPECT_EQ(WEXITSTATUS(wstatus), 3) << "the write should fail with an I/O error";
  EXPECT_EQ(ReadFile(target), "old complete file");
  EXPECT_EQ(testing::ListDir(dir), std::vector<std::string>{"map.lmap"}) << "temporary left";
  EXPECT_FALSE(WriteFileAtomic(dir + "/no/such/folder/map.lmap", "x").ok());
}

TEST(FileIoTest, WriteIntoAReadOnlyFileSystemFails) {
  // /proc is read-only for new files even for root.
  const Status status = WriteFileAtomic("/proc/linemap-test.lmap", "x");
  EXPECT_FALSE(status.ok());
  EXPECT_NE(status.message().find("/proc/linemap-test.lmap"), std::string::npos);
}

TEST(FileIoTest, KilledSaveLeavesOldOrNewCompleteFile) {
  const std::string dir = MakeTempDir("fio");
  const std::string target = dir + "/map.lmap";
  constexpr std::size_t kSize = 256 * 1024;
  WriteFile(target, Version('a', kSize));
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> delay_us(0, 20000);
  int saw_new = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const char next = static_cast<char>('b' + trial % 20);
    const pid_t pid = ::fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
      for (;;) (void)WriteFileAtomic(target, Version(next, kSize));
    }
    ::usleep(static_cast<useconds_t>(delay_us(rng)));
    ::kill(pid, SIGKILL);
    ::waitpid(pid, nullptr, 0);
    const std::string data = ReadFile(target);
    ASSERT_TRUE(IsWholeVersion(data, kSize)) << "torn file after kill in trial " << trial;
    if (data[0] == next) ++saw_new;
  }
  // The kills landed at different moments: some saves finished, some did not.
  EXPECT_GT(saw_new, 0);
}

}  // namespace
}  // namespace linemap
