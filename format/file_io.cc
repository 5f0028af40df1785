#include "format/file_io.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
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

// Writes `data` to a new temporary file beside `path`; flushes it to disk
// when `durability` is kSynced.
StatusOr<std::string> WriteTemporary(const std::string& path, std::string_view data,
                                     Durability durability) {
  if (path.empty()) return InvalidArgumentError("empty output file name");
  if (IsDirectory(path)) {
    return InvalidArgumentError(Quoted(path) + " is a directory; give a file name");
  }
  std::string tmp = path + ".tmp-XXXXXX";
  const int fd = ::mkstemp(tmp.data());
  if (fd < 0) {
    return IoError("cannot create a file in " + Quoted(DirectoryOf(path)) + " for " + Quoted(path) +
                   ": " + ErrnoText(errno));
  }
  Status status = WriteAll(fd, data, path);
  if (status.ok() && durability == Durability::kSynced && ::fsync(fd) != 0) {
    status = IoError("cannot flush " + Quoted(path) + " to disk: " + ErrnoText(errno));
  }
  if (status.ok()) {
    // mkstemp creates files 0600; give the file the mode a plain create would.
    const mode_t mask = ::umask(0);
    ::umask(mask);
    ::fchmod(fd, 0666 & ~mask);
  }
  if (::close(fd) != 0 && status.ok()) {
    status = IoError("cannot close " + Quoted(path) + ": " + ErrnoText(errno));
  }
  if (!status.ok()) {
    ::unlink(tmp.c_str());
    return status;
  }
  return tmp;
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
  std::vector<std::string> temporaries;
  auto remove_temporaries = [&temporaries](std::size_t from) {
    for (std::size_t i = from; i < temporaries.size(); ++i) ::unlink(temporaries[i].c_str());
  };
  for (const FileToWrite& file : files) {
    StatusOr<std::string> tmp = WriteTemporary(file.path, file.data, durability);
    if (!tmp.ok()) {
      remove_temporaries(0);
      return tmp.status();
    }
    temporaries.push_back(*tmp);
  }
  for (std::size_t i = 0; i < files.size(); ++i) {
    if (::rename(temporaries[i].c_str(), files[i].path.c_str()) != 0) {
      const int err = errno;
      remove_temporaries(i);
      return IoError("cannot rename the new file onto " + Quoted(files[i].path) + ": " +
                     ErrnoText(err));
    }
  }
  if (durability == Durability::kSynced) {
    std::vector<std::string> synced;
    for (const FileToWrite& file : files) {
      const std::string dir = DirectoryOf(file.path);
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
