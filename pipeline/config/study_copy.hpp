#pragma once
// `pipeline new MY.yaml --from paper`: a study of your own from a shipped one (or any study file).
// The copy is the original's text (its comments kept) with
//   * every path (output, preparation, a test's scene, a particle file named in an override)
//     rewritten to resolve from the copy's folder to the same file as before, except
//   * output, which becomes results/<stem> beside the copy (its own results, not the original's),
//   * name, which becomes the copy's stem (my_study.yaml -> my_study).
// Asked for (CopyChanges): another results folder, and variants of its own (a study with variants
// of its own keeps them; giving it more is refused).
#include <string>
#include <vector>

namespace pipeline {

struct CopyChanges {
  std::string output;                 // the results folder, from the current folder; "": results/<stem> beside the copy
  std::vector<std::string> variants;  // each a YAML flow mapping, one entry of the copy's `variants:` list
};

// The copy's text. `from_file` is where `text` was read from (its paths are relative to it),
// `to_file` where the copy goes.
std::string study_copy_text(const std::string& text, const std::string& from_file, const std::string& to_file,
                            const CopyChanges& changes = {});

// Writes the copy of `from_file` to `to_file` and reads it back as a study (every path checked);
// an existing `to_file` is refused unless `force`. Throws dem::ConfigError.
void write_study_copy(const std::string& from_file, const std::string& to_file, bool force, const CopyChanges& changes = {});

// The study file `from` names: a path to a file, or the name of a shipped study (paper,
// decisions, ...) looked up in `folders` in order. The error lists the names found.
std::string find_study(const std::string& from, const std::vector<std::string>& folders);

}  // namespace pipeline
