#pragma once
// A run as `dem run` makes it, for every front end that starts one (the `dem` command, the Python
// module): the result's name checked, the scene read with its overrides, the result's files
// checked against the scene's inputs, OUT.lock taken, an existing OUT checked, the thread count
// set, then run_scene. What a front end adds is only how it shows progress and errors.
#include <string>
#include <utility>
#include <vector>

#include "run/run_scene.hpp"

namespace dem {

struct RunRequest {
  std::string scene_file;  // the scene's YAML file; with scene_text, the name that text goes by
  std::string scene_text;  // when not empty: the scene itself (YAML), relative paths resolved from scene_file's folder
  std::vector<std::pair<std::string, std::string>> overrides;  // (key path, YAML value), as `dem run --set KEY=VALUE`
  std::string out;         // RESULT.h5 (run/output_path.hpp says which names it may have)
  std::string input_hash;  // recorded in the result (the pipeline's)
  int threads = 1;         // asked for (run_scene may keep one: run/thread_choice.hpp)
  Resume resume = Resume::IfValid;
  bool force = false;      // replace an existing OUT that is not a complete result of this scene
};

// Makes the run. Before anything is written it throws OutputPathError (where the result may not
// go, or another run holds OUT.lock) or ConfigError (bad input: the file, the key and what is
// allowed); after that, what run_scene throws, with RESULT.h5.partial marked failed. OUT.lock is
// let go however the run ends.
RunSummary run_request(const RunRequest& request, const RunObserver& observer = {});

}  // namespace dem
