#include "io/file_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

namespace dem {

FileLock::FileLock(std::string path) : path_(std::move(path)) {
  for (int attempt = 0; attempt < 100; ++attempt) {
    const int fd = open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
    if (fd < 0) {
      error_ = "cannot create the lock file " + path_ + ": " + std::strerror(errno);
      return;
    }
    if (flock(fd, LOCK_EX | LOCK_NB) != 0) {
      const int e = errno;
      close(fd);
      if (e != EWOULDBLOCK) error_ = "cannot lock " + path_ + ": " + std::strerror(e);
      return;  // held by another process: error_ stays ""
    }
    // Still the file at the path? (Its holder may have removed it between our open and flock.)
    struct stat mine{}, there{};
    if (fstat(fd, &mine) == 0 && stat(path_.c_str(), &there) == 0 && mine.st_dev == there.st_dev && mine.st_ino == there.st_ino) {
      fd_ = fd;
      return;
    }
    close(fd);
  }
  error_ = "cannot lock " + path_ + ": it keeps being replaced";
}

FileLock::~FileLock() {
  if (fd_ < 0) return;
  unlink(path_.c_str());  // while held: a taker that opened it before sees it gone and tries again
  close(fd_);
}

void FileLock::note(const std::string& text) const {
  if (fd_ < 0) return;
  if (ftruncate(fd_, 0) != 0) return;
  for (std::size_t done = 0; done < text.size();) {
    const ssize_t n = pwrite(fd_, text.data() + done, text.size() - done, static_cast<off_t>(done));
    if (n <= 0) return;  // a note is a courtesy: the lock holds without it
    done += static_cast<std::size_t>(n);
  }
}

bool FileLock::held_by_a_process(const std::string& path) {
  struct stat st{};
  if (stat(path.c_str(), &st) != 0) return false;
  // A line of /proc/locks: "1: FLOCK  ADVISORY  WRITE 4242 08:01:123456 0 EOF" (device major:minor
  // in hex, then the inode).
  char id[64];
  std::snprintf(id, sizeof id, "%02x:%02x:%llu", major(st.st_dev), minor(st.st_dev), static_cast<unsigned long long>(st.st_ino));
  std::ifstream locks("/proc/locks");
  for (std::string line; std::getline(locks, line);) {
    std::istringstream fields(line);
    for (std::string f; fields >> f;)
      if (f == id) return true;
  }
  return false;
}

std::string FileLock::read_note(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace dem
