#include "io/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <vector>

namespace dem {

namespace {

[[noreturn]] void fail(const std::string& file, const std::string& what, int err) {
  throw std::runtime_error(file + ": " + what + ": " + std::strerror(err));
}

std::string folder_of(const std::string& file) {
  const std::filesystem::path parent = std::filesystem::path(file).parent_path();
  return parent.empty() ? "." : parent.string();
}

// A tool writes a file of its own: the rename would put a regular file where a device node, a FIFO
// or a link was (as root, over /dev/full), so anything but a regular file is left alone.
void refuse_non_regular(const std::string& path, const std::string& file) {
  if (const std::string kind = non_regular_kind(path); !kind.empty())
    throw std::runtime_error(path + ": is " + kind + ", not a regular file: refused (writing " + file +
                             " replaces only a regular file or makes a new one); give the path of a regular file");
}

}  // namespace

std::string non_regular_kind(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  switch (fs::symlink_status(path, ec).type()) {
    case fs::file_type::not_found:
    case fs::file_type::regular: return "";
    case fs::file_type::directory: return "a directory";
    case fs::file_type::symlink: return "a symbolic link";
    case fs::file_type::character: return "a character device";
    case fs::file_type::block: return "a block device";
    case fs::file_type::fifo: return "a FIFO (named pipe)";
    case fs::file_type::socket: return "a socket";
    default: return ec ? "not readable (" + ec.message() + ")" : "not a regular file";
  }
}

std::string write_temp_beside(const std::string& file, const std::string& text) {
  // A name no other writer uses: this process's id and a count, and O_EXCL for a file of that
  // name that a process of the same id left behind (then the next count).
  static std::atomic<unsigned> count{0};
  std::string tmp;
  int fd = -1;
  for (int tries = 0; fd < 0; ++tries) {
    tmp = file + ".tmp." + std::to_string(::getpid()) + "." + std::to_string(count++);
    fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC | O_NOFOLLOW, 0644);
    if (fd < 0 && (errno != EEXIST || tries >= 100)) fail(tmp, "cannot be created", errno);
  }
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int err = n < 0 ? errno : ENOSPC;
      ::close(fd);
      ::unlink(tmp.c_str());
      fail(tmp, "cannot be written", err);
    }
    done += static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0) {
    const int err = errno;
    ::close(fd);
    ::unlink(tmp.c_str());
    fail(tmp, "cannot be flushed to disk", err);
  }
  if (::close(fd) != 0) {
    const int err = errno;
    ::unlink(tmp.c_str());
    fail(tmp, "cannot be closed", err);
  }
  return tmp;
}

void write_file_atomically(const std::string& file, const std::string& text) {
  refuse_non_regular(file, file);  // the temporary file is new (O_EXCL): only the target can be something else
  const std::string tmp = write_temp_beside(file, text);
  if (std::rename(tmp.c_str(), file.c_str()) != 0) {
    const int err = errno;
    ::unlink(tmp.c_str());
    fail(file, "cannot replace it", err);
  }
  sync_folder_of(file);
}

void sync_file(const std::string& file) {
  const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) fail(file, "cannot be opened to flush it to disk", errno);
  const int rc = ::fsync(fd);
  const int err = errno;
  ::close(fd);
  if (rc != 0) fail(file, "cannot be flushed to disk", err);
}

void sync_folder_of(const std::string& file) {
  const std::string dir = folder_of(file);
  const int dfd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dfd < 0) fail(dir, "cannot be opened to flush it to disk", errno);
  const int rc = ::fsync(dfd);
  const int err = errno;
  ::close(dfd);
  if (rc != 0) fail(dir, "cannot be flushed to disk", err);
}

void copy_file_contents(const std::string& from, const std::string& to) {
  const int in = ::open(from.c_str(), O_RDONLY | O_CLOEXEC);
  if (in < 0) fail(from, "cannot be opened", errno);
  const int out = ::open(to.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC | O_NOFOLLOW, 0644);
  if (out < 0) {
    const int err = errno;
    ::close(in);
    fail(to, "cannot be created", err);
  }
  std::vector<char> buffer(1 << 20);
  int err = 0;
  std::string failed;
  while (err == 0) {
    const ssize_t n = ::read(in, buffer.data(), buffer.size());
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) err = errno, failed = from + ": cannot be read";
    if (n <= 0) break;
    for (ssize_t done = 0; done < n;) {
      const ssize_t w = ::write(out, buffer.data() + done, static_cast<std::size_t>(n - done));
      if (w < 0 && errno == EINTR) continue;
      if (w <= 0) {
        err = w < 0 ? errno : ENOSPC, failed = to + ": cannot be written";
        break;
      }
      done += w;
    }
  }
  ::close(in);
  if (::close(out) != 0 && err == 0) err = errno, failed = to + ": cannot be closed";
  if (err != 0) throw std::runtime_error(failed + ": " + std::strerror(err));
}

void rename_durably(const std::string& from, const std::string& to) {
  if (std::rename(from.c_str(), to.c_str()) != 0) fail(from, "cannot be renamed to " + to, errno);
  sync_folder_of(to);
}

}  // namespace dem
