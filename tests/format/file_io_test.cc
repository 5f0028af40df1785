// Atomic saves: a process killed at any moment while saving leaves either the
// old complete file or the new complete file; a save that fails (file size
// limit as a stand-in for a full disk, a missing folder) leaves the old file.
#include "format/file_io.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sched.h>
#include <signal.h>
#include <sys/mount.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <ctime>
#include <random>
#include <string>
#include <vector>

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

// Any name open() takes can be saved, up to the longest a file system
// allows (255 bytes): the temporary's name, the target's plus 19 bytes,
// is cut to fit.
TEST(FileIoTest, TargetsWithTheLongestNamesAreSaved) {
  const std::string dir = MakeTempDir("fio");
  for (std::size_t length : {236u, 237u, 250u, 255u}) {
    SCOPED_TRACE(length);
    const std::string name = std::string(length - 5, 'm') + ".lmap";
    const std::string target = dir + "/" + name;
    const int fd = ::open(target.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0644);
    ASSERT_GE(fd, 0) << "the file system takes no name of " << length << " bytes";
    ::close(fd);
    ::unlink(target.c_str());
    for (Durability durability : {Durability::kSynced, Durability::kUnsynced}) {
      ASSERT_TRUE(WriteFileAtomic(target, "first", durability).ok());
      const Status replaced = WriteFileAtomic(target, "second", durability);
      ASSERT_TRUE(replaced.ok()) << replaced.ToString();
      StatusOr<std::vector<std::uint8_t>> bytes = ReadFileBytes(target, 100);
      ASSERT_TRUE(bytes.ok());
      EXPECT_EQ(std::string(bytes->begin(), bytes->end()), "second");
    }
    EXPECT_EQ(testing::ListDir(dir), std::vector<std::string>{name});
    ::unlink(target.c_str());
  }
  // One byte more is refused as open() refuses it.
  const std::string too_long = dir + "/" + std::string(256, 'm');
  const Status refused = WriteFileAtomic(too_long, "x");
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.sys_errno(), ENAMETOOLONG) << refused.ToString();
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
    if (status.ok()) _exit(0);
    if (status.code() != StatusCode::kIoError) _exit(4);
    _exit(status.sys_errno() == EFBIG ? 3 : 5);  // write(2) fails so over RLIMIT_FSIZE
  }
  int wstatus = 0;
  ::waitpid(pid, &wstatus, 0);
  ASSERT_TRUE(WIFEXITED(wstatus));
  EXPECT_EQ(WEXITSTATUS(wstatus), 3) << "the write should fail with an I/O error, errno EFBIG";
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

// A writable file on a file system mounted read-only: the refusal carries
// EROFS, as open() gives it, not the EACCES of a read-only file. Needs a
// private mount namespace (root); skipped without one.
TEST(FileIoTest, ReplacingAFileOnAReadOnlyMountCarriesErofs) {
  const std::string dir = MakeTempDir("fio_rofs");
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    if (::unshare(CLONE_NEWNS) != 0 ||
        ::mount(nullptr, "/", nullptr, MS_REC | MS_PRIVATE, nullptr) != 0 ||
        ::mount("none", dir.c_str(), "tmpfs", 0, nullptr) != 0) {
      _exit(77);
    }
    const std::string target = dir + "/map.lmap";
    if (!WriteFileAtomic(target, "old").ok()) _exit(4);
    if (::mount(nullptr, dir.c_str(), nullptr, MS_REMOUNT | MS_RDONLY, nullptr) != 0) _exit(77);
    if (::access(target.c_str(), W_OK) == 0 || errno != EROFS) _exit(77);
    const Status replaced = WriteFileAtomic(target, "new");
    if (replaced.ok()) _exit(5);
    if (replaced.sys_errno() != EROFS) _exit(6);
    if (replaced.message().find("read-only, mode") != std::string::npos) _exit(7);
    _exit(CheckSaveTarget(target).sys_errno() == EROFS ? 0 : 8);
  }
  int wstatus = 0;
  ::waitpid(pid, &wstatus, 0);
  ASSERT_TRUE(WIFEXITED(wstatus));
  if (WEXITSTATUS(wstatus) == 77) GTEST_SKIP() << "no private mount namespace here";
  EXPECT_EQ(WEXITSTATUS(wstatus), 0) << "4: first save failed, 5: replaced, 6: errno not EROFS, "
                                        "7: called the file read-only, 8: CheckSaveTarget";
}

mode_t ModeOf(const std::string& path) {
  struct stat st;
  EXPECT_EQ(::stat(path.c_str(), &st), 0) << path;
  return st.st_mode & 07777;
}

bool IsSymlink(const std::string& path) {
  struct stat st;
  return ::lstat(path.c_str(), &st) == 0 && S_ISLNK(st.st_mode);
}

// A "current map" symlink stays a symlink: the file it points at gets the
// new contents (through a chain of links and a relative target too).
TEST(FileIoTest, SaveThroughASymlinkReplacesItsTarget) {
  const std::string dir = MakeTempDir("fio_link");
  ::mkdir((dir + "/maps").c_str(), 0755);
  WriteFile(dir + "/maps/real.lmap", "old");
  ASSERT_EQ(::symlink("maps/real.lmap", (dir + "/current.lmap").c_str()), 0);
  ASSERT_EQ(::symlink("current.lmap", (dir + "/alias.lmap").c_str()), 0);
  ASSERT_TRUE(WriteFileAtomic(dir + "/current.lmap", "new").ok());
  EXPECT_TRUE(IsSymlink(dir + "/current.lmap"));
  EXPECT_EQ(ReadFile(dir + "/maps/real.lmap"), "new");
  ASSERT_TRUE(WriteFileAtomic(dir + "/alias.lmap", "newer", Durability::kUnsynced).ok());
  EXPECT_TRUE(IsSymlink(dir + "/alias.lmap"));
  EXPECT_TRUE(IsSymlink(dir + "/current.lmap"));
  EXPECT_EQ(ReadFile(dir + "/maps/real.lmap"), "newer");
  // Absolute targets, and a dangling link creates the file it names.
  ASSERT_EQ(::symlink((dir + "/maps/later.lmap").c_str(), (dir + "/next.lmap").c_str()), 0);
  ASSERT_TRUE(WriteFileAtomic(dir + "/next.lmap", "created").ok());
  EXPECT_TRUE(IsSymlink(dir + "/next.lmap"));
  EXPECT_EQ(ReadFile(dir + "/maps/later.lmap"), "created");
  EXPECT_EQ(testing::ListDir(dir + "/maps"), (std::vector<std::string>{"later.lmap", "real.lmap"}));
  // A loop is an error naming the file, and writes nothing.
  ASSERT_EQ(::symlink("loop_b.lmap", (dir + "/loop_a.lmap").c_str()), 0);
  ASSERT_EQ(::symlink("loop_a.lmap", (dir + "/loop_b.lmap").c_str()), 0);
  const Status loop = WriteFileAtomic(dir + "/loop_a.lmap", "x");
  EXPECT_FALSE(loop.ok());
  EXPECT_NE(loop.message().find("loop_a.lmap"), std::string::npos) << loop.message();
}

TEST(FileIoTest, ReplacedFileKeepsItsPermissionBits) {
  const std::string dir = MakeTempDir("fio_mode");
  const std::string target = dir + "/map.lmap";
  WriteFile(target, "old");
  ASSERT_EQ(::chmod(target.c_str(), 0640), 0);
  ASSERT_TRUE(WriteFileAtomic(target, "new").ok());
  EXPECT_EQ(ReadFile(target), "new");
  EXPECT_EQ(ModeOf(target), 0640u);
  ASSERT_EQ(::chmod(target.c_str(), 0604), 0);
  ASSERT_TRUE(WriteFileAtomic(target, "newer").ok());
  EXPECT_EQ(ModeOf(target), 0604u);
  // A new file gets the mode a plain create gives (0666 less the umask).
  const mode_t mask = ::umask(022);
  ASSERT_TRUE(WriteFileAtomic(dir + "/fresh.lmap", "x").ok());
  ::umask(mask);
  EXPECT_EQ(ModeOf(dir + "/fresh.lmap"), 0644u);
}

// A read-only file is refused, not replaced, even for root (which the
// permission bits do not stop): the file and the folder stay as they were.
TEST(FileIoTest, ReadOnlyFileIsRefused) {
  const std::string dir = MakeTempDir("fio_ro");
  const std::string target = dir + "/map.lmap";
  WriteFile(target, "keep me");
  ASSERT_EQ(::chmod(target.c_str(), 0444), 0);
  const Status status = WriteFileAtomic(target, "new");
  EXPECT_EQ(status.code(), StatusCode::kIoError);
  EXPECT_NE(status.message().find("map.lmap"), std::string::npos) << status.message();
  EXPECT_NE(status.message().find("read-only"), std::string::npos) << status.message();
  EXPECT_EQ(ReadFile(target), "keep me");
  EXPECT_EQ(ModeOf(target), 0444u);
  // Through a symlink too, and in a pair nothing is written.
  ASSERT_EQ(::symlink("map.lmap", (dir + "/link.lmap").c_str()), 0);
  EXPECT_FALSE(WriteFileAtomic(dir + "/link.lmap", "new").ok());
  EXPECT_FALSE(WriteFilesAtomic({{dir + "/other.pgm", "pgm"}, {target, "yaml"}}).ok());
  EXPECT_EQ(testing::ListDir(dir), (std::vector<std::string>{"link.lmap", "map.lmap"}));
  EXPECT_EQ(ReadFile(target), "keep me");
  ASSERT_EQ(::chmod(target.c_str(), 0644), 0);
}

TEST(FileIoTest, IsSameFileSeesLinks) {
  const std::string dir = MakeTempDir("fio_same");
  WriteFile(dir + "/a.pgm", "a");
  WriteFile(dir + "/b.pgm", "a");
  ASSERT_EQ(::link((dir + "/a.pgm").c_str(), (dir + "/hard.pgm").c_str()), 0);
  ASSERT_EQ(::symlink("a.pgm", (dir + "/soft.pgm").c_str()), 0);
  EXPECT_TRUE(IsSameFile(dir + "/a.pgm", dir + "/a.pgm"));
  EXPECT_TRUE(IsSameFile(dir + "/a.pgm", dir + "/./hard.pgm"));
  EXPECT_TRUE(IsSameFile(dir + "/soft.pgm", dir + "/a.pgm"));
  EXPECT_FALSE(IsSameFile(dir + "/a.pgm", dir + "/b.pgm"));
  EXPECT_FALSE(IsSameFile(dir + "/a.pgm", dir + "/missing.pgm"));
  EXPECT_FALSE(IsSameFile(dir + "/missing.pgm", dir + "/missing.pgm"));
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

TEST(FileIoTest, SaveKilledWhileWritingLeavesNoTemporaryFile) {
  // The new file has no name until it is written (and flushed): killed
  // meanwhile, the save leaves the old file and nothing beside it.
  const std::string dir = MakeTempDir("fio");
  const std::string target = dir + "/map.lmap";
  WriteFile(target, Version('a', 1024));
  int started[2];
  ASSERT_EQ(::pipe(started), 0);
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    // 96 MB: writing and flushing it takes far longer than the 2 ms below.
    const std::string data = Version('b', std::size_t{96} << 20);
    const char go = 1;
    (void)!::write(started[1], &go, 1);
    (void)WriteFileAtomic(target, data);
    ::_exit(0);
  }
  char go = 0;
  ASSERT_EQ(::read(started[0], &go, 1), 1);
  ::usleep(2000);
  ::kill(pid, SIGKILL);
  ::waitpid(pid, nullptr, 0);
  ::close(started[0]);
  ::close(started[1]);
  EXPECT_EQ(testing::ListDir(dir), std::vector<std::string>{"map.lmap"});
  // The old file, or (should a loaded machine delay the kill past the
  // rename) the whole new one.
  const std::string data = ReadFile(target);
  EXPECT_TRUE(IsWholeVersion(data, 1024) || IsWholeVersion(data, std::size_t{96} << 20));
}

// Sets the modification time of `path` to `age_s` seconds ago.
void AgeFile(const std::string& path, long age_s) {
  const std::time_t then = std::time(nullptr) - age_s;
  const struct timeval times[2] = {{then, 0}, {then, 0}};
  ASSERT_EQ(::utimes(path.c_str(), times), 0) << path;
}

TEST(FileIoTest, SaveRemovesOnlyStaleTemporariesOfItsOwnTarget) {
  // A save killed between naming its temporary and the rename leaves one;
  // the next save of the same target removes it once it is old enough to
  // belong to no live save, and leaves every other file alone.
  const std::string dir = MakeTempDir("fio");
  const std::string target = dir + "/map.lmap";
  WriteFile(target, Version('a', 16));
  const std::vector<std::string> stale = {"map.lmap.linemap-tmp-0a1b2c",
                                          "map.lmap.linemap-tmp-Xy9QzW"};
  const std::vector<std::string> kept = {
      "map.lmap.linemap-tmp-d4e5f6",    // fresh: may be a live save's
      "map.lmap.linemap-tmp-0a1b2",     // 5 characters: not a name a save gives
      "map.lmap.linemap-tmp-0a1b2c7",   // 7 characters
      "map.lmap.linemap-tmp-0a1b-c",    // not a letter or digit
      "other.lmap.linemap-tmp-0a1b2c",  // another target's
      "map.lmap.tmp-backup",            // the user's, named like many tools' temporaries
      "map.lmap.bak",                   // the user's
  };
  for (const std::string& name : stale) WriteFile(dir + "/" + name, "x");
  for (const std::string& name : kept) WriteFile(dir + "/" + name, "x");
  for (const std::string& name : stale) AgeFile(dir + "/" + name, kStaleTemporarySeconds + 5);
  for (std::size_t i = 1; i < kept.size(); ++i) {
    AgeFile(dir + "/" + kept[i], kStaleTemporarySeconds + 5);
  }
  AgeFile(dir + "/" + kept[0], kStaleTemporarySeconds - 60);
  ASSERT_TRUE(WriteFileAtomic(target, Version('b', 16)).ok());
  std::vector<std::string> expected = kept;
  expected.push_back("map.lmap");
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(testing::ListDir(dir), expected);
  EXPECT_TRUE(IsWholeVersion(ReadFile(target), 16));
  EXPECT_EQ(ReadFile(target)[0], 'b');
}

// A target of 250 bytes: its temporaries' names hold its first 236, or
// fewer where byte 236 is inside a UTF-8 character (here "é", 2 bytes, from
// byte 235: the name is cut before it).
TEST(FileIoTest, StaleTemporariesOfALongNamedTargetAreRemoved) {
  std::string accented = "a";
  while (accented.size() < 249) accented += "\xC3\xA9";  // é
  const std::pair<std::string, std::string> cases[] = {
      {std::string(245, 'm') + ".lmap", std::string(236, 'm')},
      {accented + ".lmap", accented.substr(0, 235)},
  };
  for (const auto& [name, kept_bytes] : cases) {
    const std::string dir = MakeTempDir("fio");
    const std::string stale = kept_bytes + ".linemap-tmp-0a1b2c";
    WriteFile(dir + "/" + stale, "x");
    AgeFile(dir + "/" + stale, kStaleTemporarySeconds + 5);
    ASSERT_TRUE(WriteFileAtomic(dir + "/" + name, Version('a', 16)).ok());
    EXPECT_EQ(testing::ListDir(dir), std::vector<std::string>{name});
  }
}

// Streamed saves (AtomicFileWriter): the pieces land where they were
// written, and the target changes only at Commit().
TEST(AtomicFileWriterTest, PiecesLandInPlaceAndReplaceTheFileOnlyOnCommit) {
  const std::string dir = MakeTempDir("afw");
  const std::string target = dir + "/map.pgm";
  WriteFile(target, "old");
  StatusOr<AtomicFileWriter> writer = AtomicFileWriter::Open(target);
  ASSERT_TRUE(writer.ok()) << writer.status().message();
  ASSERT_TRUE(writer->Append("head").ok());
  ASSERT_TRUE(writer->WriteAt(10, "tail").ok());
  ASSERT_TRUE(writer->WriteAt(4, "ab").ok());
  ASSERT_TRUE(writer->Append("!").ok());  // after the furthest byte so far
  EXPECT_EQ(writer->size(), 15u);
  EXPECT_EQ(ReadFile(target), "old");
  EXPECT_EQ(testing::ListDir(dir), std::vector<std::string>{"map.pgm"});
  ASSERT_TRUE(writer->Commit().ok());
  EXPECT_EQ(ReadFile(target), std::string("headab\0\0\0\0tail!", 15));
  EXPECT_EQ(testing::ListDir(dir), std::vector<std::string>{"map.pgm"});
  EXPECT_FALSE(writer->Append("late").ok());
}

TEST(AtomicFileWriterTest, WriterDroppedBeforeCommitLeavesTheOldFile) {
  const std::string dir = MakeTempDir("afw");
  const std::string target = dir + "/map.pgm";
  WriteFile(target, "old");
  {
    StatusOr<AtomicFileWriter> writer = AtomicFileWriter::Open(target, Durability::kUnsynced);
    ASSERT_TRUE(writer.ok());
    ASSERT_TRUE(writer->Append(Version('n', 1 << 16)).ok());
  }
  EXPECT_EQ(ReadFile(target), "old");
  EXPECT_EQ(testing::ListDir(dir), std::vector<std::string>{"map.pgm"});
  // Refused up front, as WriteFileAtomic refuses them.
  EXPECT_EQ(AtomicFileWriter::Open(dir).status().code(), StatusCode::kInvalidArgument);
  EXPECT_FALSE(AtomicFileWriter::Open(dir + "/no/such/folder/map.pgm").ok());
}

// SaveLmap opens its writer before a long encode: what happens to the
// target meanwhile is what the commit goes by. A file made read-only is
// refused then; one replaced meanwhile gives its own mode to the new file.
TEST(AtomicFileWriterTest, CommitLooksAtTheTargetAgain) {
  const std::string dir = MakeTempDir("afw_again");
  const std::string target = dir + "/map.lmap";
  WriteFile(target, "old");
  StatusOr<AtomicFileWriter> writer = AtomicFileWriter::Open(target);
  ASSERT_TRUE(writer.ok()) << writer.status().message();
  ASSERT_EQ(::chmod(target.c_str(), 0444), 0);
  ASSERT_TRUE(writer->Append("new").ok());
  const Status refused = writer->Commit();
  EXPECT_FALSE(refused.ok());
  EXPECT_NE(refused.message().find("read-only"), std::string::npos) << refused.message();
  EXPECT_EQ(ReadFile(target), "old");
  EXPECT_EQ(ModeOf(target), 0444u);
  ASSERT_EQ(::chmod(target.c_str(), 0644), 0);
  // Opened while there was no file; one with mode 0640 appeared meanwhile.
  const std::string fresh = dir + "/fresh.lmap";
  StatusOr<AtomicFileWriter> second = AtomicFileWriter::Open(fresh);
  ASSERT_TRUE(second.ok()) << second.status().message();
  WriteFile(fresh, "theirs");
  ASSERT_EQ(::chmod(fresh.c_str(), 0640), 0);
  ASSERT_TRUE(second->Append("ours").ok());
  ASSERT_TRUE(second->Commit().ok());
  EXPECT_EQ(ReadFile(fresh), "ours");
  EXPECT_EQ(ModeOf(fresh), 0640u);
  EXPECT_EQ(testing::ListDir(dir), (std::vector<std::string>{"fresh.lmap", "map.lmap"}));
}

// CheckSaveTarget refuses what Open refuses, and leaves no trace either way.
TEST(FileIoTest, CheckSaveTargetRefusesWhatOpenRefusesAndCreatesNothing) {
  const std::string dir = MakeTempDir("fio_check");
  WriteFile(dir + "/ro.lmap", "keep");
  ASSERT_EQ(::chmod((dir + "/ro.lmap").c_str(), 0444), 0);
  ASSERT_EQ(::symlink("missing/map.lmap", (dir + "/dangling.lmap").c_str()), 0);
  const std::vector<std::string> refused = {"",
                                            dir,
                                            dir + "/ro.lmap",
                                            dir + "/no/map.lmap",
                                            dir + "/dangling.lmap",
                                            dir + "/ro.lmap/x.lmap"};
  for (const std::string& path : refused) {
    EXPECT_FALSE(CheckSaveTarget(path).ok()) << path;
    EXPECT_FALSE(AtomicFileWriter::Open(path).ok()) << path;
  }
  EXPECT_TRUE(CheckSaveTarget(dir + "/new.lmap").ok());
  EXPECT_TRUE(
      CheckSaveTarget(dir + "/../" + dir.substr(dir.find_last_of('/') + 1) + "/n.lmap").ok());
  EXPECT_EQ(testing::ListDir(dir), (std::vector<std::string>{"dangling.lmap", "ro.lmap"}));
  EXPECT_EQ(ReadFile(dir + "/ro.lmap"), "keep");
  ASSERT_EQ(::chmod((dir + "/ro.lmap").c_str(), 0644), 0);
}

// The errno `path` gives a plain create, the reference the library's
// refusals are held to; 0 when it succeeds (the file it made is removed).
int CreateErrno(const std::string& path) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) return errno;
  ::close(fd);
  ::unlink(path.c_str());
  return 0;
}

// Each refusal carries the errno open() gives for the same path, whether
// from a call that failed (the folder) or standing in for one (a directory,
// a symlink loop, a read-only file).
TEST(FileIoTest, SaveRefusalsCarryTheErrnoOpenGives) {
  const std::string dir = MakeTempDir("fio_errno");
  WriteFile(dir + "/file", "x");
  ASSERT_EQ(::mkdir((dir + "/folder.lmap").c_str(), 0755), 0);
  ASSERT_EQ(::symlink("missing/map.lmap", (dir + "/dangling.lmap").c_str()), 0);
  ASSERT_EQ(::symlink("loop-b.lmap", (dir + "/loop-a.lmap").c_str()), 0);
  ASSERT_EQ(::symlink("loop-a.lmap", (dir + "/loop-b.lmap").c_str()), 0);
  WriteFile(dir + "/ro.lmap", "keep");
  ASSERT_EQ(::chmod((dir + "/ro.lmap").c_str(), 0444), 0);
  std::vector<std::string> paths = {dir + "/no/map.lmap", dir + "/file/map.lmap",
                                    dir + "/folder.lmap", dir + "/dangling.lmap",
                                    dir + "/loop-a.lmap"};
  // Root's open() writes a read-only file, which the library refuses
  // anyway (ReadOnlyFileIsRefusedWithEacces).
  if (::geteuid() != 0) paths.push_back(dir + "/ro.lmap");
  for (const std::string& path : paths) {
    const int expected = CreateErrno(path);
    ASSERT_NE(expected, 0) << path << ": open() should have refused it";
    const Status checked = CheckSaveTarget(path);
    EXPECT_EQ(checked.sys_errno(), expected)
        << path << ": " << std::strerror(expected) << " expected, " << checked.message();
    const Status opened = AtomicFileWriter::Open(path).status();
    EXPECT_EQ(opened.sys_errno(), expected)
        << path << ": " << std::strerror(expected) << " expected, " << opened.message();
  }
  EXPECT_EQ(AtomicFileWriter::Open(dir + "/folder.lmap").status().sys_errno(), EISDIR);
  EXPECT_EQ(WriteFileAtomic(dir + "/no/map.lmap", "x").sys_errno(), ENOENT);
  EXPECT_EQ(testing::ListDir(dir),
            (std::vector<std::string>{"dangling.lmap", "file", "folder.lmap", "loop-a.lmap",
                                      "loop-b.lmap", "ro.lmap"}));
  ASSERT_EQ(::chmod((dir + "/ro.lmap").c_str(), 0644), 0);
}

// A folder that takes no new file although its permission bits say it
// does: CheckSaveTarget cannot see it, but Open reports the errno the
// create gave, not a guess.
TEST(FileIoTest, OpenInAPseudoFileSystemCarriesTheCreatesErrno) {
  const std::string path = "/proc/linemap-errno-test.lmap";
  const int expected = CreateErrno(path);
  if (expected == 0) GTEST_SKIP() << path << " could be created here";
  const Status opened = AtomicFileWriter::Open(path).status();
  EXPECT_EQ(opened.code(), StatusCode::kIoError);
  EXPECT_EQ(opened.sys_errno(), expected) << opened.message();
}

TEST(FileIoTest, ReadOnlyFileIsRefusedWithEacces) {
  const std::string dir = MakeTempDir("fio_ro_errno");
  WriteFile(dir + "/ro.lmap", "keep");
  ASSERT_EQ(::chmod((dir + "/ro.lmap").c_str(), 0444), 0);
  EXPECT_EQ(CheckSaveTarget(dir + "/ro.lmap").sys_errno(), EACCES);
  EXPECT_EQ(WriteFileAtomic(dir + "/ro.lmap", "new").sys_errno(), EACCES);
  EXPECT_EQ(ReadFile(dir + "/ro.lmap"), "keep");
  ASSERT_EQ(::chmod((dir + "/ro.lmap").c_str(), 0644), 0);
}

// Read failures carry the errno of open(path, O_RDONLY), and a directory
// the EISDIR reading it gives.
TEST(FileIoTest, ReadFailuresCarryTheErrnoOpenGives) {
  const std::string dir = MakeTempDir("fio_read_errno");
  WriteFile(dir + "/file", "x");
  WriteFile(dir + "/locked", "x");
  ASSERT_EQ(::chmod((dir + "/locked").c_str(), 0), 0);
  std::vector<std::string> paths = {dir + "/missing", dir + "/no/missing", dir + "/file/x"};
  if (::access((dir + "/locked").c_str(), R_OK) != 0) paths.push_back(dir + "/locked");
  for (const std::string& path : paths) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    const int expected = fd < 0 ? errno : 0;
    if (fd >= 0) ::close(fd);
    ASSERT_NE(expected, 0) << path;
    const Status read = ReadFileBytes(path, 100).status();
    EXPECT_EQ(read.sys_errno(), expected) << path << ": " << read.message();
    EXPECT_EQ(InputFile::Open(path).status().sys_errno(), expected) << path;
  }
  EXPECT_EQ(ReadFileBytes(dir + "/missing", 100).status().code(), StatusCode::kNotFound);
  const Status directory = ReadFileBytes(dir, 100).status();
  EXPECT_EQ(directory.code(), StatusCode::kInvalidArgument);
  EXPECT_EQ(directory.sys_errno(), EISDIR);
  // Not a system call's failure: no errno.
  WriteFile(dir + "/big", std::string(101, 'x'));
  EXPECT_EQ(ReadFileBytes(dir + "/big", 100).status().sys_errno(), 0);
  ASSERT_EQ(::chmod((dir + "/locked").c_str(), 0644), 0);
}

// A pair committed together: a failed write in either (a 64 KiB file-size
// limit standing in for a full disk) leaves both old files.
TEST(AtomicFileWriterTest, FailedWriteInAPairLeavesBothOldFiles) {
  const std::string dir = MakeTempDir("afw");
  WriteFile(dir + "/map.pgm", "old pgm");
  WriteFile(dir + "/map.yaml", "old yaml");
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    ::signal(SIGXFSZ, SIG_IGN);
    struct rlimit limit = {1 << 16, 1 << 16};
    ::setrlimit(RLIMIT_FSIZE, &limit);
    StatusOr<AtomicFileWriter> pgm = AtomicFileWriter::Open(dir + "/map.pgm");
    StatusOr<AtomicFileWriter> yaml = AtomicFileWriter::Open(dir + "/map.yaml");
    if (!pgm.ok() || !yaml.ok()) _exit(5);
    Status status;
    for (int piece = 0; piece < 4 && status.ok(); ++piece) {
      status = pgm->Append(Version('n', 1 << 15));
    }
    if (status.ok()) _exit(6);  // the limit should have stopped the third piece
    if (!yaml->Append("new yaml").ok()) _exit(7);
    const Status committed = CommitFilesAtomic({&*pgm, &*yaml});
    _exit(committed.ok() ? 0 : (committed.code() == StatusCode::kIoError ? 3 : 4));
  }
  int wstatus = 0;
  ::waitpid(pid, &wstatus, 0);
  ASSERT_TRUE(WIFEXITED(wstatus));
  EXPECT_EQ(WEXITSTATUS(wstatus), 3) << "the commit should fail with the write's I/O error";
  EXPECT_EQ(ReadFile(dir + "/map.pgm"), "old pgm");
  EXPECT_EQ(ReadFile(dir + "/map.yaml"), "old yaml");
  EXPECT_EQ(testing::ListDir(dir), (std::vector<std::string>{"map.pgm", "map.yaml"}));
}

TEST(AtomicFileWriterTest, KilledStreamedSaveLeavesOldOrNewCompleteFile) {
  const std::string dir = MakeTempDir("afw");
  const std::string target = dir + "/map.pgm";
  constexpr std::size_t kPiece = 64 * 1024;
  constexpr int kPieces = 4;
  WriteFile(target, Version('a', kPiece * kPieces));
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> delay_us(0, 20000);
  int saw_new = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const char next = static_cast<char>('b' + trial % 20);
    const pid_t pid = ::fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
      const std::string piece = Version(next, kPiece);
      for (;;) {
        StatusOr<AtomicFileWriter> writer = AtomicFileWriter::Open(target);
        if (!writer.ok()) continue;
        for (int i = 0; i < kPieces; ++i) (void)writer->Append(piece);
        (void)writer->Commit();
      }
    }
    ::usleep(static_cast<useconds_t>(delay_us(rng)));
    ::kill(pid, SIGKILL);
    ::waitpid(pid, nullptr, 0);
    const std::string data = ReadFile(target);
    ASSERT_TRUE(IsWholeVersion(data, kPiece * kPieces))
        << "torn file after kill in trial " << trial;
    if (data[0] == next) ++saw_new;
  }
  EXPECT_GT(saw_new, 0);
  // Only a kill in the instant between naming and renaming can leave a
  // temporary; the target itself is always whole (checked above).
  for (const std::string& name : testing::ListDir(dir)) {
    EXPECT_TRUE(name == "map.pgm" || name.rfind("map.pgm.linemap-tmp-", 0) == 0) << name;
  }
}

}  // namespace
}  // namespace linemap

namespace linemap {
namespace {

TEST(HasExtensionTest, MatchesTheExtensionInAnyCaseAfterAName) {
  EXPECT_TRUE(HasExtension("map.yaml", ".yaml"));
  EXPECT_TRUE(HasExtension("dir/MAP.YAML", ".yaml"));
  EXPECT_TRUE(HasExtension("out.Lmap", ".LMAP"));
  EXPECT_TRUE(HasExtension("a.b.pgm", ".pgm"));
  EXPECT_FALSE(HasExtension(".yaml", ".yaml"));  // no name before it
  EXPECT_FALSE(HasExtension("map.yml", ".yaml"));
  EXPECT_FALSE(HasExtension("mapyaml", ".yaml"));
  EXPECT_FALSE(HasExtension("", ".bag"));
  EXPECT_FALSE(HasExtension("map.yaml.bak", ".yaml"));
}

}  // namespace
}  // namespace linemap
