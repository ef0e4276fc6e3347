#pragma once
// Where `dem run --out OUT` may write: the one place that decides. A run writes, replaces, removes
// or locks a family of files named after OUT (result_family):
//
//   OUT                    the result, once complete
//   OUT.partial            the result while the run goes on, and after it failed
//   OUT.checkpoint(.tmp)   the newest checkpoint (and the one being written)
//   OUT.lock               held (flock) by the one run that writes the family
//   OUT.outcome            the pipeline's record of a run that stopped
//   R.xdmf                 the XDMF view of a complete result (R = OUT without .h5)
//
// Refused before anything is written, each with a message naming --out (or the scene key) and
// what is allowed; `dem` exits 2:
//   * OUT whose extension is not .h5 or .hdf5 (a result is HDF5; `dem table --csv` writes text);
//   * OUT ending in .partial, .checkpoint, .lock, .outcome, .tmp or .xdmf: it is (or could be) a
//     file of another result's family, which that run's lock does not cover;
//   * OUT in a folder that does not exist or that this user cannot write to;
//   * any existing member of the family that is not a regular file (folder, device node, FIFO,
//     socket, symbolic link): the run would replace it or write through it;
//   * any member of the family that is an input of the run: the scene file or a file a scene key
//     names (SceneConfig::input_files), by path or as the same file (hard link);
//   * an existing OUT that is not a complete result of this same scene (scene text and input
//     hash): replacing it needs --force (the pipeline passes it for its own results).
#include <stdexcept>
#include <string>
#include <vector>

#include "config/scene_config.hpp"

namespace dem {

struct OutputPathError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct FamilyFile {
  std::string role, path;  // e.g. {"its partial result", "r.h5.partial"}
};
std::vector<FamilyFile> result_family(const std::string& out);

// The name suffixes --out may not end in (".partial", ...).
const std::vector<std::string>& reserved_suffixes();

// Before the scene is read: the name, the folder, the kind of every existing family member.
void check_output_name(const std::string& out);
// After the scene is read: no member of the family is an input of the run.
void check_output_not_input(const std::string& out, const SceneConfig& scene);
// Under the lock (so that no other run completes OUT in between): an existing OUT is replaced
// only if it is a complete result of this scene with this input hash, or with `force`.
void check_output_replaceable(const std::string& out, const SceneConfig& scene, const std::string& input_hash, bool force);

}  // namespace dem
