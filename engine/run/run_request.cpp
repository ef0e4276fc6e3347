#include "run/run_request.hpp"

#include <omp.h>

#include <new>

#include "config/scene_config.hpp"
#include "config/yaml_section.hpp"  // ConfigError
#include "io/file_lock.hpp"
#include "run/output_path.hpp"

namespace dem {

RunSummary run_request(const RunRequest& r, const RunObserver& observer) {
  // Where the result goes (run/output_path.hpp): its name and folder first, then what the scene
  // reads, then, under the lock, what is there now.
  check_output_name(r.out);
  SceneConfig scene;
  try {
    scene = r.scene_text.empty() ? load_scene(r.scene_file, r.overrides) : scene_from_text(r.scene_text, r.scene_file, r.overrides);
  } catch (const ConfigError&) {
    throw;
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::exception& e) {  // whatever stops a scene from being read is bad input
    throw ConfigError(e.what());
  }
  check_output_not_input(r.out, scene);
  // One writer per result: a second run to the same OUT refuses instead of writing into the same
  // partial file and checkpoint. The lock goes with the process, however it ends; names another
  // result's files use (.partial, ...) are refused above, so it covers the whole family. The lock
  // file is removed however the run ends (refused, failed or complete): io/file_lock.hpp.
  const FileLock lock(r.out + ".lock");
  if (!lock.held())
    throw OutputPathError("--out " + r.out + ": " +
                          (lock.error().empty() ? "another dem run is writing this result (it holds " + r.out + ".lock)" : lock.error()));
  check_output_replaceable(r.out, scene, r.input_hash, r.force);
  omp_set_num_threads(r.threads);
  if (observer.stop && *observer.stop)  // asked to stop while the scene was read: nothing is written
    throw RunInterrupted("interrupted by signal " + std::to_string(*observer.stop) + " before the run started; nothing was written");
  return run_scene(scene, r.out, observer, r.input_hash, r.resume);
}

}  // namespace dem
