#include "format/file_io.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>

namespace linemap {
namespace {

std::string Quoted(const std::string& path) { return "'" + path + "'"; }

std::string ErrnoText(int err) { return std::strerror(err); }

std::string DirectoryOf(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  if (slash == 0) return "/";
  return path.substr(0, slash);
}

Status WriteAll(int fd, std::string_view data, const std::string& path) {
  const char* p = data.data();
  std::size_t left = data.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, p, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      return IoError("cannot write " + Quoted(path) + ": " + ErrnoText(errno));
    }
    p += n;
    left -= static_cast<std::size_t>(n);
  }
  return Status::Ok();
}

}  // namespace

bool IsDirectory(const std::string& path) {
  struct stat st;
  return ::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode);
}

bool IsSameFile(const std::string& a, const std::string& b) {
  struct stat sa, sb;
  return ::stat(a.c_str(), &sa) == 0 && ::stat(b.c_str(), &sb) == 0 && sa.st_dev == sb.st_dev &&
         sa.st_ino == sb.st_ino;
}

StatusOr<std::vector<std::uint8_t>> ReadFileBytes(const std::string& path,
                                                  std::uint64_t max_bytes) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) {
    const int err = errno;
    if (err == ENOENT) return NotFoundError(Quoted(path) + ": no such file");
    // An input the caller cannot open is bad input, not a failure of ours.
    return InvalidArgumentError("cannot open " + Quoted(path) + ": " + ErrnoText(err));
  }
  struct stat st;
  if (::fstat(fd, &st) != 0) {
    const int err = errno;
    ::close(fd);
    return IoError("cannot stat " + Quoted(path) + ": " + ErrnoText(err));
  }
  if (S_ISDIR(st.st_mode)) {
    ::close(fd);
    return InvalidArgumentError(Quoted(path) + " is a directory, not a file");
  }
  if (static_cast<std::uint64_t>(st.st_size) > max_bytes) {
    ::close(fd);
    return ResourceExhaustedError(Quoted(path) + " is " + std::to_string(st.st_size) +
                                  " bytes, more than the limit of " + std::to_string(max_bytes));
  }
  std::vector<std::uint8_t> bytes;
  bytes.reserve(static_cast<std::size_t>(st.st_size));
  std::uint8_t buffer[1 << 16];
  for (;;) {
    const ssize_t n = ::read(fd, buffer, sizeof(buffer));
    if (n < 0) {
      if (errno == EINTR) continue;
      const int err = errno;
      ::close(fd);
      // Reading a directory opened on some systems fails with EISDIR.
      if (err == EISDIR) return InvalidArgumentError(Quoted(path) + " is a directory");
      return InvalidArgumentError("cannot read " + Quoted(path) + ": " + ErrnoText(err));
    }
    if (n == 0) break;
    if (bytes.size() + static_cast<std::size_t>(n) > max_bytes) {
      ::close(fd);
      return ResourceExhaustedError(Quoted(path) + " is larger than the limit of " +
                                    std::to_string(max_bytes) + " bytes");
    }
    bytes.insert(bytes.end(), buffer, buffer + n);
  }
  ::close(fd);
  return bytes;
}

namespace {

constexpr int kMaxSymlinkHops = 40;  // as the kernel's ELOOP limit

// Where a save to `path` must go: the file at the end of a chain of symlinks
// (so a "current map" link keeps pointing at the new contents), or `path`
// itself when it is not a symlink. A dangling link gives the file it names.
StatusOr<std::string> ResolveTarget(const std::string& path) {
  std::string target = path;
  for (int hop = 0; hop < kMaxSymlinkHops; ++hop) {
    struct stat st;
    if (::lstat(target.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return target;
    std::string link(static_cast<std::size_t>(st.st_size > 0 ? st.st_size : 255) + 1, '\0');
    const ssize_t n = ::readlink(target.c_str(), link.data(), link.size());
    if (n < 0) {
      return IoError("cannot read the symlink " + Quoted(target) + ": " + ErrnoText(errno));
    }
    if (static_cast<std::size_t>(n) >= link.size()) {
      return IoError("the symlink " + Quoted(target) + " changed while being read");
    }
    link.resize(static_cast<std::size_t>(n));
    target = link[0] == '/' ? link : DirectoryOf(target) + "/" + link;
  }
  return IoError(Quoted(path) + ": too many levels of symbolic links");
}

// What a replaced file keeps: its permission bits and owner.
struct ExistingFile {
  bool exists = false;
  struct stat st = {};
};

// Refuses to replace a file the caller may not write (as cp without -f
// does): one with no write permission for us, or none for anyone (root may
// write anything, but a 0444 map was made read-only on purpose).
StatusOr<ExistingFile> CheckReplaceable(const std::string& path, const std::string& target) {
  ExistingFile existing;
  // A target that cannot be looked at (missing, or its folder is) is
  // created; creating the temporary file beside it reports what is wrong.
  if (::stat(target.c_str(), &existing.st) != 0) return existing;
  existing.exists = true;
  if (S_ISDIR(existing.st.st_mode)) {
    return InvalidArgumentError(Quoted(path) + " is a directory; give a file name");
  }
  if (!S_ISREG(existing.st.st_mode)) {
    return InvalidArgumentError(Quoted(path) + " is not a regular file; not replacing it");
  }
  if (::access(target.c_str(), W_OK) != 0 || (existing.st.st_mode & 0222) == 0) {
    char mode[8];
    std::snprintf(mode, sizeof(mode), "%04o", static_cast<unsigned>(existing.st.st_mode & 07777));
    return IoError("cannot replace " + Quoted(path) + ": " + ErrnoText(EACCES) +
                   " (the file is read-only, mode " + mode + "; make it writable or remove it)");
  }
  return existing;
}

// A new file beside a save's target: unnamed (O_TMPFILE; `fd` open) until
// NameTemporary links it, or named from the start (`name`; `fd` closed)
// where the file system has no unnamed files.
struct Temporary {
  int fd = -1;
  std::string name;
};

// Writes `data` to a new temporary file beside `target`, the file `path`
// resolves to; flushes it to disk when `durability` is kSynced. The file has
// no name while it is written, so a save killed meanwhile leaves nothing
// behind; `named` asks for a named one at once. It gets the permission bits
// (and, where allowed, the owner) of an existing `target`, else the mode a
// plain create would give.
StatusOr<Temporary> WriteTemporary(const std::string& path, const std::string& target,
                                   const ExistingFile& existing, std::string_view data,
                                   Durability durability, bool named) {
  Temporary tmp;
  int fd = named ? -1 : ::open(DirectoryOf(target).c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0600);
  if (fd < 0) {  // no unnamed files here (old kernel, some file systems)
    tmp.name = target + ".tmp-XXXXXX";
    fd = ::mkstemp(tmp.name.data());
    if (fd < 0) {
      return IoError("cannot create a file in " + Quoted(DirectoryOf(target)) + " for " +
                     Quoted(path) + ": " + ErrnoText(errno));
    }
  }
  Status status = WriteAll(fd, data, path);
  if (status.ok() && durability == Durability::kSynced && ::fsync(fd) != 0) {
    status = IoError("cannot flush " + Quoted(path) + " to disk: " + ErrnoText(errno));
  }
  if (status.ok()) {
    mode_t mode = 0;
    if (existing.exists) {
      mode = existing.st.st_mode & 0777;
      // Best effort, as the replaced file's owner is not ours to insist on:
      // only root (or the owner, for the group) may give a file away.
      (void)::fchown(fd, existing.st.st_uid, existing.st.st_gid);
    } else {
      // New files start 0600; give the file the mode a plain create would.
      const mode_t mask = ::umask(0);
      ::umask(mask);
      mode = 0666 & ~mask;
    }
    if (::fchmod(fd, mode) != 0) {
      status = IoError("cannot set the permissions of " + Quoted(path) + ": " + ErrnoText(errno));
    }
  }
  if (tmp.name.empty() && status.ok()) {
    tmp.fd = fd;  // closed when named
    return tmp;
  }
  if (::close(fd) != 0 && status.ok()) {
    status = IoError("cannot close " + Quoted(path) + ": " + ErrnoText(errno));
  }
  if (!status.ok()) {
    if (!tmp.name.empty()) ::unlink(tmp.name.c_str());
    return status;
  }
  return tmp;
}

// Gives an unnamed temporary a name beside `target` (just before the rename,
// so a killed save leaves a named temporary only in that instant) and closes
// it. False, with the temporary untouched, when it cannot be linked (no
// /proc): the caller writes a named one instead.
bool NameTemporary(Temporary* tmp, const std::string& target) {
  if (!tmp->name.empty()) return true;
  const std::string fd_path = "/proc/self/fd/" + std::to_string(tmp->fd);
  // A name no other save uses: the clock and the process id, retried on a clash.
  const std::uint64_t seed =
      static_cast<std::uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count()) ^
      (static_cast<std::uint64_t>(::getpid()) << 32);
  for (std::uint64_t attempt = 0; attempt < 100; ++attempt) {
    char suffix[24];
    std::snprintf(suffix, sizeof(suffix), ".tmp-%06llx",
                  static_cast<unsigned long long>((seed + attempt * 0x9e3779b9u) & 0xffffff));
    const std::string name = target + suffix;
    if (::linkat(AT_FDCWD, fd_path.c_str(), AT_FDCWD, name.c_str(), AT_SYMLINK_FOLLOW) == 0) {
      tmp->name = name;
      ::close(tmp->fd);
      tmp->fd = -1;
      return true;
    }
    if (errno != EEXIST) return false;
  }
  return false;
}

// Closes or removes what is left of temporaries that were not renamed.
void DiscardTemporaries(std::vector<Temporary>* temporaries, std::size_t from) {
  for (std::size_t i = from; i < temporaries->size(); ++i) {
    Temporary& tmp = (*temporaries)[i];
    if (tmp.fd >= 0) ::close(tmp.fd);  // unnamed: the file goes with it
    if (!tmp.name.empty()) ::unlink(tmp.name.c_str());
  }
}

void SyncDirectory(const std::string& dir) {
  const int dir_fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir_fd >= 0) {
    ::fsync(dir_fd);
    ::close(dir_fd);
  }
}

}  // namespace

Status WriteFilesAtomic(const std::vector<FileToWrite>& files, Durability durability) {
  // Every target is resolved and checked before anything is written.
  std::vector<std::string> targets;
  std::vector<ExistingFile> existing;
  for (const FileToWrite& file : files) {
    if (file.path.empty()) return InvalidArgumentError("empty output file name");
    LINEMAP_ASSIGN_OR_RETURN(std::string target, ResolveTarget(file.path));
    LINEMAP_ASSIGN_OR_RETURN(ExistingFile old, CheckReplaceable(file.path, target));
    targets.push_back(std::move(target));
    existing.push_back(old);
  }
  std::vector<Temporary> temporaries;
  for (std::size_t i = 0; i < files.size(); ++i) {
    StatusOr<Temporary> tmp = WriteTemporary(files[i].path, targets[i], existing[i], files[i].data,
                                             durability, /*named=*/false);
    if (!tmp.ok()) {
      DiscardTemporaries(&temporaries, 0);
      return tmp.status();
    }
    temporaries.push_back(std::move(*tmp));
  }
  // Every file is written; now each gets a name and takes its target's.
  for (std::size_t i = 0; i < files.size(); ++i) {
    if (!NameTemporary(&temporaries[i], targets[i])) {
      StatusOr<Temporary> named = WriteTemporary(files[i].path, targets[i], existing[i],
                                                 files[i].data, durability, /*named=*/true);
      if (!named.ok()) {
        DiscardTemporaries(&temporaries, 0);
        return named.status();
      }
      ::close(temporaries[i].fd);
      temporaries[i] = std::move(*named);
    }
  }
  for (std::size_t i = 0; i < files.size(); ++i) {
    if (::rename(temporaries[i].name.c_str(), targets[i].c_str()) != 0) {
      const int err = errno;
      DiscardTemporaries(&temporaries, i);
      return IoError("cannot rename the new file onto " + Quoted(files[i].path) + ": " +
                     ErrnoText(err));
    }
  }
  if (durability == Durability::kSynced) {
    std::vector<std::string> synced;
    for (const std::string& target : targets) {
      const std::string dir = DirectoryOf(target);
      if (std::find(synced.begin(), synced.end(), dir) != synced.end()) continue;
      SyncDirectory(dir);
      synced.push_back(dir);
    }
  }
  return Status::Ok();
}

Status WriteFileAtomic(const std::string& path, std::string_view data, Durability durability) {
  return WriteFilesAtomic({{path, data}}, durability);
}

}  // namespace linemap
