// Whole-file reads with a size limit, and atomic whole-file writes.
#ifndef LINEMAP_FORMAT_FILE_IO_H_
#define LINEMAP_FORMAT_FILE_IO_H_

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "linemap/map_io.h"
#include "linemap/status.h"

namespace linemap {

// Reads all of `path`. Fails with kNotFound for a missing file,
// kInvalidArgument for a directory or a file that cannot be opened or read
// (bad input: the CLI exits 2), kResourceExhausted when it is larger than
// `max_bytes`.
// Messages name the file.
StatusOr<std::vector<std::uint8_t>> ReadFileBytes(const std::string& path, std::uint64_t max_bytes);

// Writes `data` to a temporary file in the same directory, flushes it to
// disk (fsync, unless `durability` is kUnsynced), then renames it over
// `path` and syncs the directory. On any failure the temporary file is
// removed and an existing `path` is untouched. The temporary file has no
// name while it is written (O_TMPFILE, linked under a name just before the
// rename), so a process killed meanwhile leaves nothing behind; where the
// file system has no unnamed files (or /proc is missing), it is named
// `path.tmp-XXXXXX` from the start.
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

// True when `path` names an existing directory.
bool IsDirectory(const std::string& path);

// True when `a` and `b` both exist and are the same file (same device and
// inode, after following symlinks): hard links and symlinks included.
bool IsSameFile(const std::string& a, const std::string& b);

}  // namespace linemap

#endif  // LINEMAP_FORMAT_FILE_IO_H_
