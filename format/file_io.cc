#include "format/file_io.h"

#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <string>
#include <utility>

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

StatusOr<InputFile> InputFile::Open(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) {
    const int err = errno;
    if (err == ENOENT) return NotFoundError(Quoted(path) + ": no such file").WithErrno(err);
    // An input the caller may not read is bad input, not a failure of ours
    // (exit 2), but a kind of its own: Python raises PermissionError.
    if (err == EACCES || err == EPERM) {
      return PermissionDeniedError("cannot open " + Quoted(path) + ": " + ErrnoText(err))
          .WithErrno(err);
    }
    return InvalidArgumentError("cannot open " + Quoted(path) + ": " + ErrnoText(err))
        .WithErrno(err);
  }
  struct stat st;
  if (::fstat(fd, &st) != 0) {
    const int err = errno;
    ::close(fd);
    return IoError("cannot stat " + Quoted(path) + ": " + ErrnoText(err)).WithErrno(err);
  }
  if (S_ISDIR(st.st_mode)) {
    ::close(fd);
    // Opening a directory for reading succeeds; reading it is what fails.
    return InvalidArgumentError(Quoted(path) + " is a directory, not a file").WithErrno(EISDIR);
  }
  const bool regular = S_ISREG(st.st_mode);
  return InputFile(path, fd, regular, regular ? static_cast<std::uint64_t>(st.st_size) : 0);
}

InputFile::InputFile(InputFile&& other) noexcept
    : path_(std::move(other.path_)),
      fd_(std::exchange(other.fd_, -1)),
      regular_(other.regular_),
      size_(other.size_) {}

InputFile& InputFile::operator=(InputFile&& other) noexcept {
  if (this != &other) {
    if (fd_ >= 0) ::close(fd_);
    path_ = std::move(other.path_);
    fd_ = std::exchange(other.fd_, -1);
    regular_ = other.regular_;
    size_ = other.size_;
  }
  return *this;
}

InputFile::~InputFile() {
  if (fd_ >= 0) ::close(fd_);
}

StatusOr<std::size_t> InputFile::Read(std::uint8_t* out, std::size_t size) {
  std::size_t done = 0;
  while (done < size) {
    const ssize_t n = ::read(fd_, out + done, size - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      const int err = errno;
      // Reading a directory opened on some systems fails with EISDIR.
      if (err == EISDIR) {
        return InvalidArgumentError(Quoted(path_) + " is a directory").WithErrno(err);
      }
      return InvalidArgumentError("cannot read " + Quoted(path_) + ": " + ErrnoText(err))
          .WithErrno(err);
    }
    if (n == 0) break;
    done += static_cast<std::size_t>(n);
  }
  return done;
}

StatusOr<std::vector<std::uint8_t>> ReadFileBytes(const std::string& path, std::uint64_t max_bytes,
                                                  Limit which) {
  LINEMAP_ASSIGN_OR_RETURN(InputFile file, InputFile::Open(path));
  if (file.size() > max_bytes) {
    return OverLimitError(which, Quoted(path) + " is " + std::to_string(file.size()) +
                                     " bytes, more than the limit of " + std::to_string(max_bytes));
  }
  std::vector<std::uint8_t> bytes;
  bytes.reserve(static_cast<std::size_t>(file.size()));
  std::uint8_t buffer[1 << 16];
  for (;;) {
    LINEMAP_ASSIGN_OR_RETURN(const std::size_t n, file.Read(buffer, sizeof(buffer)));
    if (n == 0) break;
    if (bytes.size() + n > max_bytes) {
      return OverLimitError(which, Quoted(path) + " is larger than the limit of " +
                                       std::to_string(max_bytes) + " bytes");
    }
    bytes.insert(bytes.end(), buffer, buffer + n);
  }
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
      const int err = errno;
      return IoError("cannot read the symlink " + Quoted(target) + ": " + ErrnoText(err))
          .WithErrno(err);
    }
    if (static_cast<std::size_t>(n) >= link.size()) {
      return IoError("the symlink " + Quoted(target) + " changed while being read");
    }
    link.resize(static_cast<std::size_t>(n));
    target = link[0] == '/' ? link : DirectoryOf(target) + "/" + link;
  }
  // ELOOP: what open() says after as many hops.
  return IoError(Quoted(path) + ": too many levels of symbolic links").WithErrno(ELOOP);
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
  // A name too long for the file system is refused now: only the rename at
  // the end would see it, after the work.
  if (::stat(target.c_str(), &existing.st) != 0) {
    const int err = errno;
    if (err == ENAMETOOLONG) {
      return IoError("cannot write " + Quoted(path) + ": " + ErrnoText(err)).WithErrno(err);
    }
    return existing;
  }
  existing.exists = true;
  // The refusals stand in for open(target, O_WRONLY | O_CREAT) and carry
  // the errno it gives: EISDIR for a directory, EACCES for a file without
  // write permission (for root too, whose open() would write it).
  if (S_ISDIR(existing.st.st_mode)) {
    return InvalidArgumentError(Quoted(path) + " is a directory; give a file name")
        .WithErrno(EISDIR);
  }
  if (!S_ISREG(existing.st.st_mode)) {
    return InvalidArgumentError(Quoted(path) + " is not a regular file; not replacing it");
  }
  const int denied = ::access(target.c_str(), W_OK) == 0 ? 0 : errno;
  if ((existing.st.st_mode & 0222) == 0 || denied == EACCES || denied == EPERM) {
    const int err = denied != 0 ? denied : EACCES;
    char mode[8];
    std::snprintf(mode, sizeof(mode), "%04o", static_cast<unsigned>(existing.st.st_mode & 07777));
    return IoError("cannot replace " + Quoted(path) + ": " + ErrnoText(err) +
                   " (the file is read-only, mode " + mode + "; make it writable or remove it)")
        .WithErrno(err);
  }
  if (denied != 0) {  // EROFS: a writable file on a read-only file system, ...
    return IoError("cannot replace " + Quoted(path) + ": " + ErrnoText(denied)).WithErrno(denied);
  }
  return existing;
}

constexpr char kTemporaryMarker[] = ".linemap-tmp-";
// A file name's longest (NAME_MAX on Linux's file systems): a temporary's
// name is the target's, the marker and 6 letters or digits, so the target's
// name is cut to leave them room (open() takes a target of 255 bytes).
constexpr std::size_t kMaxFileName = 255;
constexpr std::size_t kTemporaryTail = sizeof(kTemporaryMarker) - 1 + 6;

// The file name `base` (of a target) as a temporary's name starts with it:
// the whole name, or its first bytes when the temporary's would be too long,
// cut before a character rather than inside one (file systems that check
// UTF-8 refuse a name ending in part of a character).
std::string TemporaryBase(const std::string& base) {
  std::size_t cut = kMaxFileName - kTemporaryTail;
  if (base.size() <= cut) return base;
  while (cut > 0 && (static_cast<unsigned char>(base[cut]) & 0xC0) == 0x80) --cut;
  return base.substr(0, cut);
}

// A temporary's path for `target` without its 6 last characters.
std::string TemporaryPrefix(const std::string& target) {
  const std::size_t slash = target.find_last_of('/');
  const std::size_t name_start = slash == std::string::npos ? 0 : slash + 1;
  return target.substr(0, name_start) + TemporaryBase(target.substr(name_start)) + kTemporaryMarker;
}

// A name for a temporary beside `target` that no other save uses: the
// clock and the process id, varied by `attempt` on a clash.
std::string TemporaryName(const std::string& target, std::uint64_t attempt) {
  const std::uint64_t seed =
      static_cast<std::uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count()) ^
      (static_cast<std::uint64_t>(::getpid()) << 32);
  char suffix[8];
  std::snprintf(suffix, sizeof(suffix), "%06llx",
                static_cast<unsigned long long>((seed + attempt * 0x9e3779b9u) & 0xffffff));
  return TemporaryPrefix(target) + suffix;
}

std::string ProcFdPath(int fd) { return "/proc/self/fd/" + std::to_string(fd); }

// True for `name` == TemporaryBase(`base`) + ".linemap-tmp-" + 6 ASCII
// letters or digits: the names TemporaryName and mkstemp give the
// temporaries of target `base` (a marker no user file is likely to carry,
// unlike ".tmp-"). Targets whose names share their first 236 bytes share
// their temporaries' names; only stale ones are ever removed.
bool IsTemporaryOf(const std::string& name, const std::string& base) {
  const std::string prefix = TemporaryBase(base) + kTemporaryMarker;
  if (name.size() != prefix.size() + 6 || name.compare(0, prefix.size(), prefix) != 0) {
    return false;
  }
  return std::all_of(
      name.begin() + static_cast<std::ptrdiff_t>(prefix.size()), name.end(), [](char c) {
        return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
      });
}

// Removes the temporaries of `target` that a killed save left behind. A
// save names its unnamed file just before the rename, so a kill in that
// instant (or during a slow close or the flush of a YAML's image) leaves
// one. A temporary untouched for kStaleTemporarySeconds belongs to no live
// save, or to one that named it at Open and writes it late (a map's YAML
// after a long decode; an .lmap after a long encode, where the file system
// has no unnamed files): that save's Finish() sees its name gone and fails
// before any rename, leaving every target as it was. Best effort: failures
// to list or remove are ignored.
void RemoveStaleTemporaries(const std::string& target) {
  const std::string dir = DirectoryOf(target);
  const std::size_t slash = target.find_last_of('/');
  const std::string base = slash == std::string::npos ? target : target.substr(slash + 1);
  DIR* listing = ::opendir(dir.c_str());
  if (listing == nullptr) return;
  const std::time_t now = std::time(nullptr);
  while (const dirent* entry = ::readdir(listing)) {
    const std::string name = entry->d_name;
    if (!IsTemporaryOf(name, base)) continue;
    const std::string path = dir + "/" + name;
    struct stat st;
    // Only regular files of ours: never another user's save.
    if (::lstat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode) || st.st_uid != ::geteuid()) {
      continue;
    }
    if (now - st.st_mtime >= kStaleTemporarySeconds) ::unlink(path.c_str());
  }
  ::closedir(listing);
}

void SyncDirectory(const std::string& dir) {
  const int dir_fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir_fd >= 0) {
    ::fsync(dir_fd);
    ::close(dir_fd);
  }
}

}  // namespace

Status CheckSaveTarget(const std::string& path) {
  if (path.empty()) return InvalidArgumentError("empty output file name");
  LINEMAP_ASSIGN_OR_RETURN(std::string target, ResolveTarget(path));
  LINEMAP_RETURN_IF_ERROR(CheckReplaceable(path, target).status());
  // The folder, probed as Open creates its file: an unnamed file, gone when
  // closed. Where the file system has none (EOPNOTSUPP, or EISDIR from an
  // old kernel) the permission bits are all there is to go by.
  const std::string dir = DirectoryOf(target);
  const int fd = ::open(dir.c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0600);
  if (fd >= 0) {
    ::close(fd);
    return Status::Ok();
  }
  int err = errno;
  if (err == EOPNOTSUPP || err == EISDIR || err == EINVAL) {
    err = ::access(dir.c_str(), W_OK | X_OK) == 0 ? 0 : errno;
  }
  if (err == 0) return Status::Ok();
  return IoError("cannot create a file in " + Quoted(dir) + " for " + Quoted(path) + ": " +
                 ErrnoText(err))
      .WithErrno(err);
}

StatusOr<AtomicFileWriter> AtomicFileWriter::Open(const std::string& path, Durability durability) {
  if (path.empty()) return InvalidArgumentError("empty output file name");
  LINEMAP_ASSIGN_OR_RETURN(std::string target, ResolveTarget(path));
  LINEMAP_ASSIGN_OR_RETURN(ExistingFile existing, CheckReplaceable(path, target));
  AtomicFileWriter writer;
  writer.path_ = path;
  writer.target_ = std::move(target);
  writer.durability_ = durability;
  writer.replaces_ = existing.exists;
  writer.mode_ = existing.st.st_mode & 0777;
  writer.uid_ = existing.st.st_uid;
  writer.gid_ = existing.st.st_gid;
  RemoveStaleTemporaries(writer.target_);
  const std::string dir = DirectoryOf(writer.target_);
  int fd = ::open(dir.c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0600);
  // The unnamed file is linked under a name through /proc at the end; with
  // no /proc it could never be, so it is named from the start instead.
  if (fd >= 0 && ::access(ProcFdPath(fd).c_str(), F_OK) != 0) {
    ::close(fd);
    fd = -1;
  }
  if (fd < 0) {  // no unnamed files here (old kernel, some file systems)
    writer.temp_name_ = TemporaryPrefix(writer.target_) + "XXXXXX";
    fd = ::mkstemp(writer.temp_name_.data());
    if (fd < 0) {
      const int err = errno;
      return IoError("cannot create a file in " + Quoted(dir) + " for " + Quoted(path) + ": " +
                     ErrnoText(err))
          .WithErrno(err);
    }
    ::fcntl(fd, F_SETFD, FD_CLOEXEC);
  }
  writer.fd_ = fd;
  return writer;
}

AtomicFileWriter::AtomicFileWriter(AtomicFileWriter&& other) noexcept
    : path_(std::move(other.path_)),
      target_(std::move(other.target_)),
      durability_(other.durability_),
      replaces_(other.replaces_),
      mode_(other.mode_),
      uid_(other.uid_),
      gid_(other.gid_),
      fd_(std::exchange(other.fd_, -1)),
      temp_name_(std::exchange(other.temp_name_, std::string())),
      end_(other.end_),
      error_(std::move(other.error_)) {}

AtomicFileWriter& AtomicFileWriter::operator=(AtomicFileWriter&& other) noexcept {
  if (this != &other) {
    Discard();
    path_ = std::move(other.path_);
    target_ = std::move(other.target_);
    durability_ = other.durability_;
    replaces_ = other.replaces_;
    mode_ = other.mode_;
    uid_ = other.uid_;
    gid_ = other.gid_;
    fd_ = std::exchange(other.fd_, -1);
    temp_name_ = std::exchange(other.temp_name_, std::string());
    end_ = other.end_;
    error_ = std::move(other.error_);
  }
  return *this;
}

AtomicFileWriter::~AtomicFileWriter() { Discard(); }

void AtomicFileWriter::Discard() {
  if (fd_ >= 0) ::close(fd_);  // unnamed: the file goes with it
  fd_ = -1;
  if (!temp_name_.empty()) ::unlink(temp_name_.c_str());
  temp_name_.clear();
}

Status AtomicFileWriter::WriteAt(std::uint64_t offset, std::string_view data) {
  if (!error_.ok()) return error_;
  if (fd_ < 0) return InternalError(Quoted(path_) + ": written after it was committed");
  const char* p = data.data();
  std::size_t left = data.size();
  std::uint64_t at = offset;
  while (left > 0) {
    const ssize_t n = ::pwrite(fd_, p, left, static_cast<off_t>(at));
    if (n < 0) {
      const int err = errno;
      if (err == EINTR) continue;
      error_ = IoError("cannot write " + Quoted(path_) + ": " + ErrnoText(err)).WithErrno(err);
      return error_;
    }
    p += n;
    at += static_cast<std::uint64_t>(n);
    left -= static_cast<std::size_t>(n);
  }
  end_ = std::max(end_, at);
  return Status::Ok();
}

Status AtomicFileWriter::Append(std::string_view data) { return WriteAt(end_, data); }

Status AtomicFileWriter::Finish() {
  if (!error_.ok()) return error_;
  if (fd_ < 0) return InternalError(Quoted(path_) + ": committed twice");
  if (durability_ == Durability::kSynced && ::fsync(fd_) != 0) {
    const int err = errno;
    return IoError("cannot flush " + Quoted(path_) + " to disk: " + ErrnoText(err)).WithErrno(err);
  }
  // Looked at again: Open may have been a long encode ago (SaveLmap opens
  // before it encodes), and a file made read-only, replaced or created
  // meanwhile is what the caller now has there.
  StatusOr<ExistingFile> existing = CheckReplaceable(path_, target_);
  if (!existing.ok()) return existing.status();
  replaces_ = existing->exists;
  mode_ = existing->st.st_mode & 0777;
  uid_ = existing->st.st_uid;
  gid_ = existing->st.st_gid;
  mode_t mode = mode_;
  if (replaces_) {
    // Best effort, as the replaced file's owner is not ours to insist on:
    // only root (or the owner, for the group) may give a file away.
    (void)::fchown(fd_, uid_, gid_);
  } else {
    // New files start 0600; give the file the mode a plain create would.
    const mode_t mask = ::umask(0);
    ::umask(mask);
    mode = 0666 & ~mask;
  }
  if (::fchmod(fd_, mode) != 0) {
    const int err = errno;
    return IoError("cannot set the permissions of " + Quoted(path_) + ": " + ErrnoText(err))
        .WithErrno(err);
  }
  if (temp_name_.empty()) {
    // Named only now, just before the rename: a save killed while writing
    // leaves nothing behind.
    const std::string fd_path = ProcFdPath(fd_);
    for (std::uint64_t attempt = 0; attempt < 100 && temp_name_.empty(); ++attempt) {
      const std::string name = TemporaryName(target_, attempt);
      if (::linkat(AT_FDCWD, fd_path.c_str(), AT_FDCWD, name.c_str(), AT_SYMLINK_FOLLOW) == 0) {
        temp_name_ = name;
      } else if (const int err = errno; err != EEXIST) {
        return IoError("cannot name the new file for " + Quoted(path_) + ": " + ErrnoText(err))
            .WithErrno(err);
      }
    }
    if (temp_name_.empty()) {
      return IoError("cannot name the new file for " + Quoted(path_) + ": every name taken")
          .WithErrno(EEXIST);
    }
  }
  // A temporary named from the start and left untouched for
  // kStaleTemporarySeconds (a long decode writes a map's YAML last) may have
  // been removed by another save of the target: then no file of the set is
  // renamed (CommitFilesAtomic finishes them all first).
  struct stat named, open_file;
  if (::fstat(fd_, &open_file) != 0) {
    const int err = errno;
    return IoError("cannot stat the new file for " + Quoted(path_) + ": " + ErrnoText(err))
        .WithErrno(err);
  }
  // ENOENT also when another file has taken the name: ours is gone from it.
  if (::stat(temp_name_.c_str(), &named) != 0 || named.st_ino != open_file.st_ino ||
      named.st_dev != open_file.st_dev) {
    return IoError("the new file for " + Quoted(path_) + " was removed while it was written")
        .WithErrno(ENOENT);
  }
  const int fd = std::exchange(fd_, -1);
  if (::close(fd) != 0) {
    const int err = errno;
    return IoError("cannot close " + Quoted(path_) + ": " + ErrnoText(err)).WithErrno(err);
  }
  return Status::Ok();
}

Status AtomicFileWriter::Commit() { return CommitFilesAtomic({this}); }

Status CommitFilesAtomic(const std::vector<AtomicFileWriter*>& writers) {
  for (AtomicFileWriter* writer : writers) {
    const Status finished = writer->Finish();
    if (!finished.ok()) {
      for (AtomicFileWriter* w : writers) w->Discard();
      return finished;
    }
  }
  for (std::size_t i = 0; i < writers.size(); ++i) {
    AtomicFileWriter& w = *writers[i];
    if (::rename(w.temp_name_.c_str(), w.target_.c_str()) != 0) {
      const int err = errno;
      const Status failed =
          IoError("cannot rename the new file onto " + Quoted(w.path_) + ": " + ErrnoText(err))
              .WithErrno(err);
      for (std::size_t j = i; j < writers.size(); ++j) writers[j]->Discard();
      return failed;
    }
    w.temp_name_.clear();
  }
  if (!writers.empty() && writers[0]->durability_ == Durability::kSynced) {
    std::vector<std::string> synced;
    for (const AtomicFileWriter* w : writers) {
      const std::string dir = DirectoryOf(w->target_);
      if (std::find(synced.begin(), synced.end(), dir) != synced.end()) continue;
      SyncDirectory(dir);
      synced.push_back(dir);
    }
  }
  return Status::Ok();
}

Status WriteFilesAtomic(const std::vector<FileToWrite>& files, Durability durability) {
  // Every target is resolved and checked before anything is written.
  std::vector<AtomicFileWriter> writers;
  writers.reserve(files.size());
  for (const FileToWrite& file : files) {
    LINEMAP_ASSIGN_OR_RETURN(AtomicFileWriter writer,
                             AtomicFileWriter::Open(file.path, durability));
    writers.push_back(std::move(writer));
  }
  std::vector<AtomicFileWriter*> pointers;
  for (std::size_t i = 0; i < files.size(); ++i) {
    LINEMAP_RETURN_IF_ERROR(writers[i].Append(files[i].data));
    pointers.push_back(&writers[i]);
  }
  return CommitFilesAtomic(pointers);
}

Status WriteFileAtomic(const std::string& path, std::string_view data, Durability durability) {
  return WriteFilesAtomic({{path, data}}, durability);
}

bool HasExtension(std::string_view path, std::string_view extension) {
  if (path.size() <= extension.size()) return false;
  return std::equal(extension.begin(), extension.end(), path.end() - extension.size(),
                    [](char a, char b) {
                      return std::tolower(static_cast<unsigned char>(a)) ==
                             std::tolower(static_cast<unsigned char>(b));
                    });
}

}  // namespace linemap
