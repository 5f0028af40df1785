// Whole-file and piecewise reads with a size limit, and atomic writes: of
// whole files, or streamed piece by piece (AtomicFileWriter) so a large image
// is never held in memory.
#ifndef LINEMAP_FORMAT_FILE_IO_H_
#define LINEMAP_FORMAT_FILE_IO_H_

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "linemap/map_io.h"
#include "linemap/status.h"

namespace linemap {

// Reads all of `path`. Fails with kNotFound for a missing file,
// kInvalidArgument for a directory or a file that cannot be opened or read
// (bad input: the CLI exits 2), kResourceExhausted when it is larger than
// `max_bytes` (tagged `which`: Limit::kFileBytes when the caller's
// DecodeLimits set it, kNone for a reader's own cap such as a map YAML's).
// Messages name the file.
StatusOr<std::vector<std::uint8_t>> ReadFileBytes(const std::string& path, std::uint64_t max_bytes,
                                                  Limit which = Limit::kFileBytes);

// A file read in pieces, for inputs too large to hold whole (a 282 MB map
// image). Move-only; closes the file when destroyed.
class InputFile {
 public:
  // Opens `path`, failing as ReadFileBytes does: kNotFound for a missing
  // file, kInvalidArgument for a directory or a file that cannot be opened.
  static StatusOr<InputFile> Open(const std::string& path);

  InputFile(InputFile&& other) noexcept;
  InputFile& operator=(InputFile&& other) noexcept;
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;
  ~InputFile();

  // Reads up to `size` bytes into `out`; fewer only at the end of the file
  // (0 there). A read error is kInvalidArgument naming the file.
  StatusOr<std::size_t> Read(std::uint8_t* out, std::size_t size);

  // True for a regular file, whose size() is known up front (not a pipe or
  // a device such as /dev/zero).
  bool is_regular() const { return regular_; }
  std::uint64_t size() const { return size_; }
  const std::string& path() const { return path_; }

 private:
  InputFile(std::string path, int fd, bool regular, std::uint64_t size)
      : path_(std::move(path)), fd_(fd), regular_(regular), size_(size) {}

  std::string path_;
  int fd_ = -1;
  bool regular_ = false;
  std::uint64_t size_ = 0;
};

// Age after which a `path.linemap-tmp-XXXXXX` of ours beside `path` is
// taken for the leftover of a killed save and removed by the next save of
// `path`.
inline constexpr long kStaleTemporarySeconds = 600;

// A new version of a file written piece by piece, replacing the old one only
// when committed, with WriteFileAtomic's guarantees: the data goes to an
// unnamed temporary file beside the target (O_TMPFILE; named
// `path.linemap-tmp-XXXXXX` from the start where the file system or a
// missing /proc rules that out), is flushed (fsync, unless kUnsynced), gets
// the replaced file's permission bits, and is renamed over the target by
// Commit(). A writer destroyed without Commit() leaves the old file and no
// temporary. A process killed while writing leaves the old file whole;
// killed in the instant between naming the temporary and the rename, it
// leaves a `path.linemap-tmp-XXXXXX` behind, which the next save of `path`
// removes once it is kStaleTemporarySeconds old (a temporary named from the
// start and left untouched that long by a live save is removed too: that
// save's Commit() then fails before any rename). Move-only.
class AtomicFileWriter {
 public:
  // Resolves symlinks and refuses directories, non-regular and read-only
  // targets (as WriteFileAtomic does) before creating the temporary.
  static StatusOr<AtomicFileWriter> Open(const std::string& path,
                                         Durability durability = Durability::kSynced);

  AtomicFileWriter(AtomicFileWriter&& other) noexcept;
  AtomicFileWriter& operator=(AtomicFileWriter&& other) noexcept;
  AtomicFileWriter(const AtomicFileWriter&) = delete;
  AtomicFileWriter& operator=(const AtomicFileWriter&) = delete;
  ~AtomicFileWriter();

  // Writes `data` after the furthest byte written so far. Unbuffered: one
  // write call per Append, so callers pass pieces of 64 KiB or more.
  Status Append(std::string_view data);
  // Writes `data` at byte `offset` (the file grows as needed; bytes never
  // written read as 0), for output produced out of order.
  Status WriteAt(std::uint64_t offset, std::string_view data);
  // Flushes, names and renames the file over the target, then syncs its
  // directory (kSynced). Fails if any earlier write failed; the old file is
  // then untouched.
  Status Commit();

  const std::string& path() const { return path_; }
  std::uint64_t size() const { return end_; }

 private:
  friend Status CommitFilesAtomic(const std::vector<AtomicFileWriter*>& writers);
  AtomicFileWriter() = default;
  // Flushes, sets the mode and gives the temporary a name (fd closed).
  Status Finish();
  void Discard();

  std::string path_;    // as the caller named it, for messages
  std::string target_;  // the file path resolves to
  Durability durability_ = Durability::kSynced;
  bool replaces_ = false;  // target exists: keep its mode and owner
  unsigned mode_ = 0;
  unsigned uid_ = 0;
  unsigned gid_ = 0;
  int fd_ = -1;
  std::string temp_name_;  // empty while the temporary is unnamed
  std::uint64_t end_ = 0;
  Status error_;  // the first failed write, reported again by Commit()
};

// Commits several writers of files that belong together (a map YAML and its
// image): all are flushed and named before the first rename, so a failure
// before that leaves every old file intact. Each directory is synced once.
Status CommitFilesAtomic(const std::vector<AtomicFileWriter*>& writers);

// Writes `data` to a temporary file in the same directory, flushes it to
// disk (fsync, unless `durability` is kUnsynced), then renames it over
// `path` and syncs the directory. On any failure the temporary file is
// removed and an existing `path` is untouched. The temporary file has no
// name while it is written (O_TMPFILE, linked under a name just before the
// rename), so a process killed while writing leaves nothing behind; where
// the file system has no unnamed files (or /proc is missing), it is named
// `path.linemap-tmp-XXXXXX` from the start. Either way the next save of `path`
// removes such leftovers once they are kStaleTemporarySeconds old.
Status WriteFileAtomic(const std::string& path, std::string_view data,
                       Durability durability = Durability::kSynced);

struct FileToWrite {
  std::string path;
  std::string_view data;
};

// As WriteFileAtomic for several files that belong together (a map YAML and
// its image): every file is written and flushed under a temporary name before
// the first rename, so a failure while writing leaves all old files intact.
// Each directory involved is synced once.
Status WriteFilesAtomic(const std::vector<FileToWrite>& files,
                        Durability durability = Durability::kSynced);

// What AtomicFileWriter::Open(path) would refuse, found without creating,
// removing or changing anything: an empty name, a symlink chain that cannot
// be followed, a directory or other non-regular file or a read-only file at
// the target, a folder that is missing or takes no new file (probed with an
// unnamed file where the file system has them). A caller about to do long
// work before its save (a decode, a plan) checks first. Open still checks
// again: the file system may change meanwhile.
Status CheckSaveTarget(const std::string& path);

// True when `path` ends in `extension` (with its dot: ".yaml"), its letters
// in any case (map.YAML, OUT.Lmap), and holds at least one character before
// it (so ".yaml" alone is false, "dir/.yaml" true: callers that need a
// file name before the extension check the base name).
bool HasExtension(std::string_view path, std::string_view extension);

// True when `path` names an existing directory.
bool IsDirectory(const std::string& path);

// True when `a` and `b` both exist and are the same file (same device and
// inode, after following symlinks): hard links and symlinks included.
bool IsSameFile(const std::string& a, const std::string& b);

}  // namespace linemap

#endif  // LINEMAP_FORMAT_FILE_IO_H_
