#pragma once
// One process at a time on a file family or a folder: an exclusive flock on a lock file, taken
// without waiting. `dem run` holds OUT.lock while it writes OUT's family (run/output_path.hpp); the
// pipeline holds <results folder>/.pipeline.lock while it runs a study there.
//
// The lock file is created when missing and removed by its holder when it lets go (however the
// holder's work ended), so no empty lock file stays behind. Removing a held lock file races with a
// process that opened it just before: that one would lock a file no longer at the path, while a
// third creates a new one. So a taker checks, once locked, that the path still names the file it
// locked, and tries again if not: two holders at once cannot happen.
#include <string>

namespace dem {

class FileLock {
 public:
  // Tries to take the lock on `path` (creating it, never following a symbolic link); see held().
  explicit FileLock(std::string path);
  ~FileLock();  // held: removes the file, then lets go
  FileLock(const FileLock&) = delete;
  FileLock& operator=(const FileLock&) = delete;

  bool held() const { return fd_ >= 0; }
  // Not held: "" if another process holds it, else why the lock file could not be opened.
  const std::string& error() const { return error_; }
  // Held: replaces the lock file's content (e.g. who holds it, for the message of another taker).
  void note(const std::string& text) const;
  // Whether a process holds a lock on the file at `path` (from /proc/locks: looking takes no lock,
  // so it never stands in the way of a taker); false if there is no such file or it cannot be told.
  static bool held_by_a_process(const std::string& path);
  // The content of the lock file at `path` ("" if none): what its holder noted.
  static std::string read_note(const std::string& path);

 private:
  std::string path_, error_;
  int fd_ = -1;
};

}  // namespace dem
