// Files written whole (io/atomic_file.hpp): a regular file is replaced through <file>.tmp and a
// rename; anything else at the path or at <file>.tmp is refused and left as it was.
#include <catch2/catch.hpp>

#include <sys/stat.h>

#include <filesystem>
#include <functional>

#include "engine/io/io_test_support.hpp"
#include "io/atomic_file.hpp"

namespace fs = std::filesystem;

namespace {

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "accepted";
}

}  // namespace

TEST_CASE("write_file_atomically replaces a regular file and nothing else", "[io][atomic]") {
  const std::string dir = dem::test::scratch_dir("atomic_file");
  // A new file and a regular file replaced: the text, and no .tmp left.
  const std::string plain = dir + "/plain.txt";
  dem::write_file_atomically(plain, "one\n");
  dem::write_file_atomically(plain, "two\n");
  CHECK(dem::test::read_bytes(plain) == "two\n");
  CHECK_FALSE(fs::exists(plain + ".tmp"));

  // A FIFO (what a device node such as /dev/full is to this test: not a regular file, and one a
  // rename would replace): refused, naming it and what it is; still a FIFO. (Had the old code
  // opened a FIFO at .tmp for writing, it would have blocked: the test would hang, not pass.)
  const std::string fifo = dir + "/fifo.txt";
  REQUIRE(::mkfifo(fifo.c_str(), 0644) == 0);
  CHECK_THAT(error_of([&] { dem::write_file_atomically(fifo, "x\n"); }),
             Catch::Contains(fifo + ": is a FIFO (named pipe), not a regular file: refused"));
  CHECK(fs::is_fifo(fs::symlink_status(fifo)));
  CHECK_FALSE(fs::exists(fifo + ".tmp"));

  // A FIFO at <file>.tmp: not the writer's (its temporary file has a name of its own, created
  // exclusively), so left alone, and the file written.
  const std::string behind = dir + "/behind.txt";
  REQUIRE(::mkfifo((behind + ".tmp").c_str(), 0644) == 0);
  CHECK(error_of([&] { dem::write_file_atomically(behind, "x\n"); }) == "accepted");
  CHECK(fs::is_fifo(fs::symlink_status(behind + ".tmp")));
  CHECK(dem::test::read_bytes(behind) == "x\n");

  // A symbolic link (to a regular file): refused; the link and its target as they were.
  const std::string target = dir + "/target.txt", link = dir + "/link.txt";
  dem::test::write_text(target, "kept\n");
  fs::create_symlink(target, link);
  CHECK_THAT(error_of([&] { dem::write_file_atomically(link, "x\n"); }), Catch::Contains("is a symbolic link"));
  CHECK(fs::is_symlink(link));
  CHECK(dem::test::read_bytes(target) == "kept\n");

  // A folder: refused, with its content.
  const std::string folder = dir + "/folder";
  fs::create_directories(folder);
  dem::test::write_text(folder + "/inside.txt", "kept\n");
  CHECK_THAT(error_of([&] { dem::write_file_atomically(folder, "x\n"); }), Catch::Contains("is a directory"));
  CHECK(dem::test::read_bytes(folder + "/inside.txt") == "kept\n");

  // A character device is named as one (/dev/null exists everywhere; the test writes to no device:
  // as root, a regression would replace it).
  CHECK(dem::non_regular_kind("/dev/null") == "a character device");
  CHECK(dem::non_regular_kind(plain).empty());
  CHECK(dem::non_regular_kind(dir + "/none.txt").empty());
}
