#pragma once
// How every program of the project says why it stopped: the reason of an exception, with what the
// standard library leaves out (the path of a file system error, "out of memory" for a failed
// allocation), and the top level of a tool's main that turns any exception into that reason on
// stderr and exit status 1 instead of an abort.
#include <cstdio>
#include <exception>
#include <string>

namespace dem {

// The reason: a std::filesystem::filesystem_error as "<path>: <what the system said>" (both paths
// when it has two), a std::bad_alloc as "out of memory (std::bad_alloc)", any other exception its
// message.
std::string describe_failure(const std::exception& e);

// Runs `body` (the tool's work after its arguments were parsed) and returns its exit status; an
// exception that gets out of it is printed as "<tool>: <describe_failure>" and gives exit status 1.
template <class Body>
int guarded_main(const char* tool, Body&& body) {
  try {
    return body();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", tool, describe_failure(e).c_str());
  } catch (...) {
    std::fprintf(stderr, "%s: stopped by an unknown exception\n", tool);
  }
  return 1;
}

}  // namespace dem
