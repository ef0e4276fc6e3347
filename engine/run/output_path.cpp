#include "run/output_path.hpp"

#include <unistd.h>

#include <cctype>
#include <filesystem>

#include "io/atomic_file.hpp"
#include "io/hdf5.hpp"
#include "io/xdmf.hpp"
#include "run/checkpoint.hpp"

namespace dem {

namespace fs = std::filesystem;

namespace {

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// The same file: the same path once symbolic links, "." and ".." are resolved, or, for files
// that exist, the same file on the disk (a hard link).
bool same_file(const std::string& a, const std::string& b) {
  std::error_code ec_a, ec_b, ec;
  const fs::path ca = fs::weakly_canonical(fs::absolute(a), ec_a), cb = fs::weakly_canonical(fs::absolute(b), ec_b);
  if (!ec_a && !ec_b && ca == cb) return true;
  return fs::exists(a, ec) && fs::exists(b, ec) && fs::equivalent(a, b, ec);
}

std::string list_text(const std::vector<std::string>& items) {
  std::string text;
  for (std::size_t i = 0; i < items.size(); ++i)
    text += (i == 0 ? "" : i + 1 == items.size() ? " or " : ", ") + items[i];
  return text;
}

}  // namespace

const std::vector<std::string>& reserved_suffixes() {
  static const std::vector<std::string> suffixes = {".partial", ".checkpoint", ".lock", ".outcome", ".tmp", ".xdmf"};
  return suffixes;
}

std::vector<FamilyFile> result_family(const std::string& out) {
  const std::string xdmf = xdmf_path_for(out);
  return {{"the result", out},
          {"its partial result", out + ".partial"},
          {"its checkpoint", checkpoint_path(out)},
          {"its checkpoint being written", checkpoint_path(out) + ".tmp"},
          {"its lock", out + ".lock"},
          {"the pipeline's record of its stop", out + ".outcome"},
          {"its XDMF view", xdmf}};
}

void check_output_name(const std::string& out) {
  for (const std::string& suffix : reserved_suffixes())
    if (ends_with(out, suffix)) {
      std::string owner = out.substr(0, out.size() - suffix.size());
      if (suffix == ".xdmf") owner += ".h5";
      throw OutputPathError("--out " + out + " ends in '" + suffix + "', the name of a file kept beside the result " + owner +
                            " (a run writing " + owner + " would not see this one); --out may not end in " +
                            list_text(reserved_suffixes()) + ": give a result's own name, such as " + owner);
    }
  std::error_code ec;
  if (fs::symlink_status(out, ec).type() == fs::file_type::directory)
    throw OutputPathError("--out " + out + " is a directory, not a file name");
  if (const std::string kind = non_regular_kind(out); !kind.empty())
    throw OutputPathError("--out " + out + " is " + kind + ", not a regular file: --out must name a regular file or a new one");
  // A result is HDF5: a name that says otherwise (out.csv) would get HDF5 bytes and out.csv.xdmf.
  std::string ext = fs::path(out).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext != ".h5" && ext != ".hdf5")
    throw OutputPathError("--out " + out + ": a result is an HDF5 file, so its name must end in .h5 or .hdf5" +
                          (ext.empty() ? std::string() : " (not '" + ext + "')") +
                          "; for a text table of a result use dem table RESULT.h5 --csv");
  const fs::path folder = fs::path(out).parent_path().empty() ? fs::path(".") : fs::path(out).parent_path();
  if (!fs::is_directory(folder, ec)) throw OutputPathError("--out " + out + " is in a folder that does not exist");
  if (access(folder.c_str(), W_OK) != 0) throw OutputPathError("--out " + out + " is in a folder this user cannot write to");
  for (const FamilyFile& f : result_family(out))
    if (const std::string kind = non_regular_kind(f.path); !kind.empty())
      throw OutputPathError("--out " + out + ": " + f.path + " (" + f.role + ") is " + kind +
                            ", not a regular file; a run would write through it or replace it: remove it or choose another --out");
}

void check_output_not_input(const std::string& out, const SceneConfig& scene) {
  for (const FamilyFile& f : result_family(out))
    for (const InputFile& in : scene.input_files)
      if (same_file(f.path, in.path)) {
        const std::string what = in.key + (in.key == "the scene file" ? "" : ", a file this run reads") + " (" + in.path + ")";
        throw OutputPathError(f.path == out ? "--out " + out + " is " + what + ": choose another --out"
                                            : "--out " + out + ": " + f.path + " (" + f.role + ") would replace " + what +
                                                  ": choose another --out");
      }
}

void check_output_replaceable(const std::string& out, const SceneConfig& scene, const std::string& input_hash, bool force) {
  std::error_code ec;
  if (force || !fs::exists(fs::symlink_status(out, ec))) return;
  std::string holds;
  try {
    h5::Handle f = h5::open_file_read(out);
    const std::string status = h5::has_attribute(f, "status") ? h5::get_string_attribute(f, "status") : "";
    if (status.empty() || !h5::has_text(f, "scene_yaml")) {
      holds = "a file that is not a dem result";
    } else if (status != "complete") {
      holds = "a result with status '" + status + "'";
    } else {
      const std::string yaml = h5::read_text(f, "scene_yaml");
      const std::string hash = h5::has_attribute(f, "input_hash") ? h5::get_string_attribute(f, "input_hash") : "";
      const std::string file = h5::has_attribute(f, "scene_file") ? h5::get_string_attribute(f, "scene_file") : "?";
      if (yaml == scene.resolved_yaml && hash == input_hash) return;  // this scene's: a run again replaces it
      holds = "the complete result of another scene (of " + file + ", " +
              (yaml != scene.resolved_yaml ? std::string("its resolved scene differs from this run's")
                                           : "its input hash '" + hash + "' differs from this run's '" + input_hash + "'") +
              ")";
    }
  } catch (const h5::Error&) {
    holds = "a file that is not a dem result";
  }
  throw OutputPathError("--out " + out + " holds " + holds + "; give --force to replace it, or choose another --out");
}

}  // namespace dem
