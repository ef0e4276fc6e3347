#include "run/checkpoint.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "core/content_hash.hpp"
#include "io/atomic_file.hpp"
#include "source_hash.hpp"
#include "version.hpp"

namespace dem {

namespace {

double finite_attribute(hid_t g, const std::string& file, const std::string& name) {
  const double v = h5::get_double_attribute(g, name);
  if (!std::isfinite(v)) throw h5::Error(file + ": /checkpoint: attribute " + name + " is not finite");
  return v;
}

std::int64_t int_attribute(hid_t g, const std::string& file, const std::string& name, std::int64_t min, std::int64_t max) {
  const std::int64_t v = h5::get_int_attribute(g, name);
  if (v < min || v > max)
    throw h5::Error(file + ": /checkpoint: attribute " + name + " = " + std::to_string(v) + " is outside [" +
                    std::to_string(min) + ", " + std::to_string(max) + "]");
  return v;
}

constexpr std::int64_t most = std::numeric_limits<std::int64_t>::max();

// The fields of a checkpoint, each named once, with how it is stored: `io` is a FieldWriter or a
// FieldReader, which go through them in this order (the order of the file). A field kept for
// resuming is one line here (and, for the cursor, its member of StageCursor).
//   real:     a double attribute (read: finite)
//   integer:  an int64 attribute (read: within [min, max])
//   values:   a 1-D dataset of a fixed number of doubles with its unit (read: that many, finite)
//   optional: the same, written only when not zero (read: zero when absent)
//   rows:     an N x 3 dataset, one row per particle (read: N rows, finite)
//   pairs:    a pair list and its history (io/state_io.hpp, write_pairs / read_pairs)

// The Verlet list as the simulation holds it, with the history of every listed pair.
template <class IO, class List, class History>
void list_fields(IO& io, List& list, History& history) {
  io.pairs("verlet", list.pairs, history);
  io.rows("verlet_position_fractional_at_build", list.s_at_build);
  io.values("verlet_cell_lengths_at_build", list.lengths_at_build, "m");
  io.optional("verlet_cell_tilts_at_build", list.tilts_at_build, "m");
  io.integer("verlet_builds", list.builds, 0, most);
}

// The energy balance: one attribute per accumulated quantity.
template <class IO, class Energy>
void energy_fields(IO& io, Energy& e) {
  io.real("energy_work_by_cell", e.work_by_cell);
  io.real("energy_dissipated_damping", e.dissipated_damping);
  io.real("energy_dissipated_friction", e.dissipated_friction);
  io.real("energy_dissipated_rolling", e.dissipated_rolling);
  io.real("energy_kinetic", e.kinetic);
  io.real("energy_elastic", e.elastic);
  io.real("energy_stored_at_start", e.stored_at_start);
  io.integer("energy_started", e.started, 0, 1);
  io.values("energy_virial", e.virial, "J");
  io.optional("energy_shear_virial", e.shear_virial, "J");
}

// Where the stage loop is (run/run_scene.hpp).
template <class IO, class Cursor>
void cursor_fields(IO& io, Cursor& c) {
  io.integer("stage", c.stage, 0, 1 << 30);
  io.integer("iteration", c.i, 1, most);
  io.integer("leg", c.leg, 0, 1 << 30);
  io.integer("done_steps", c.done_steps, 0, most);
  io.real("stress_error", c.stress_error);
  io.real("unbalanced", c.unbalanced);
  io.integer("creep_window_start", c.creep_window_start, -1, most);
  io.real("creep_volume_at_start", c.creep_volume_at_start);
  io.real("creep_rate", c.creep_rate);
  io.real("max_inertial_number", c.max_inertial_number);
  io.integer("servo_steps", c.servo.steps, -1, 1 << 30);
  io.values("from", c.from_Pa, "Pa");
  io.values("sum_sq", c.sum_sq, "Pa^2");
  io.values("strain_at_leg_start", c.strain_at_leg_start, "1");
  io.values("servo_kappa", c.servo.kappa, "1");
  io.values("servo_predicted", c.servo.predicted, "Pa");
  io.values("servo_window_start", c.servo.window_start, "Pa");
  io.real("servo_kappa_shear", c.servo.kappa_shear);
  io.values("servo_predicted_shear", c.servo.predicted_shear, "Pa");
  io.values("servo_window_start_shear", c.servo.window_start_shear, "Pa");
  io.real("mean_stress_at_start", c.mean_stress_at_start);
  io.real("deviator_at_start", c.deviator_at_start);
  io.real("cycle_low", c.cycle_low);
  io.real("cycle_high", c.cycle_high);
  io.values("strain_at_start", c.strain_at_start, "1");
}

struct FieldWriter {
  hid_t g;
  void real(const char* name, double v) { h5::set_attribute(g, name, v); }
  template <class T>
  void integer(const char* name, T v, std::int64_t, std::int64_t) { h5::set_attribute(g, name, static_cast<std::int64_t>(v)); }
  template <class V>  // Vec3 or std::array<double, N>
  void values(const char* name, const V& v, const char* units) {
    h5::write(g, name, std::vector<double>(v.data(), v.data() + v.size()), 1, units);
  }
  void optional(const char* name, const Vec3& v, const char* units) {
    if (v != Vec3::Zero()) values(name, v, units);
  }
  void rows(const char* name, const std::vector<Vec3>& v) { h5::write(g, name, flatten(v), 3, "1"); }
  void pairs(const char* prefix, const PairList& pairs, const ContactHistory& history) { write_pairs(g, prefix, pairs, history); }
};

struct FieldReader {
  hid_t g;
  const std::string& file;
  std::size_t particles;  // of the state: the rows of the list's positions
  void real(const char* name, double& v) { v = finite_attribute(g, file, name); }
  template <class T>
  void integer(const char* name, T& v, std::int64_t min, std::int64_t max) {
    v = static_cast<T>(int_attribute(g, file, name, min, max));
  }
  template <class V>
  void values(const char* name, V& v, const char*) {
    std::size_t cols = 0;
    const std::vector<double> d = h5::read<double>(g, name, cols);
    if (d.size() != static_cast<std::size_t>(v.size()) || !std::all_of(d.begin(), d.end(), [](double x) { return std::isfinite(x); }))
      throw h5::Error(file + ": /checkpoint: " + name + " must be " + std::to_string(v.size()) + " finite values");
    std::copy(d.begin(), d.end(), v.data());
  }
  void optional(const char* name, Vec3& v, const char* units) {
    if (h5::exists(g, name)) values(name, v, units);
  }
  void rows(const char* name, std::vector<Vec3>& v) {
    v = read_vec3(g, file, name);
    if (v.size() != particles)
      throw h5::Error(file + ": /checkpoint/state: " + name + " has " + std::to_string(v.size()) + " rows for " +
                      std::to_string(particles) + " particles");
    for (const Vec3& s : v)
      if (!s.allFinite()) throw h5::Error(file + ": /checkpoint/state: a non-finite position at the last list build");
  }
  void pairs(const char* prefix, PairList& pairs, ContactHistory& history) {
    SavedPairs saved = read_pairs(g, file, prefix, particles);
    pairs = std::move(saved.pairs);
    history = std::move(saved.history);
  }
};

}  // namespace

std::string checkpoint_path(const std::string& out_path) { return out_path + ".checkpoint"; }

std::string run_identity(const SceneConfig& scene, const std::string& input_hash, const std::string& source_bytes) {
  std::ostringstream text;
  text << engine_source_hash << " schema " << schema_version << "\n" << input_hash << "\n" << scene.resolved_yaml;
  if (scene.particles.kind != ParticleSource::Kind::Lattice) text << "\n" << source_bytes;
  return content_hash(text.str());
}

void write_checkpoint(const std::string& partial_path, const std::string& out_path, const std::string& identity,
                      double wall_time_s, const Simulation& sim, const StageCursor& cursor) {
  const std::string final_path = checkpoint_path(out_path), tmp = final_path + ".tmp";
  try {
    copy_file_contents(partial_path, tmp);
    h5::Handle f = h5::open_file_write(tmp);
    {
      h5::Handle g = h5::create_group(f, "checkpoint");
      h5::set_attribute(g, "identity", identity);
      h5::set_attribute(g, "step", static_cast<std::int64_t>(sim.step_count()));
      h5::set_attribute(g, "time", sim.time());
      h5::set_attribute(g, "wall_time_s", wall_time_s);
      h5::Handle state = h5::create_group(g, "state");
      write_state(state, sim);
      FieldWriter to_state{state};
      const VerletList::Saved list = sim.verlet_list().saved();
      list_fields(to_state, list, sim.history());
      const EnergyBalance energy = sim.energy();  // with the dashpots' work of the last step
      energy_fields(to_state, energy);
      const h5::Handle cursor_group = h5::create_group(g, "cursor");
      FieldWriter to_cursor{cursor_group};
      cursor_fields(to_cursor, cursor);
      h5::flush_file(f, tmp);
      // The checksum of everything in the checkpoint, read back from the file: one value changed
      // afterwards (an edit, a flipped bit) and read_checkpoint refuses it.
      h5::set_attribute(g, "checksum", h5::digest(f, "checkpoint", "checksum"));
      h5::flush_file(f, tmp);  // checked while the groups are open: closing them then writes nothing
    }
    h5::close_file(f, tmp);
    sync_file(tmp);
    rename_durably(tmp, final_path);  // only a whole checkpoint, on the disk, replaces the previous one
  } catch (const std::exception& e) {
    std::error_code ec;
    std::filesystem::remove(tmp, ec);
    throw std::runtime_error("checkpoint at step " + std::to_string(sim.step_count()) + " not written: " + e.what() +
                             (std::filesystem::exists(final_path, ec) ? "; " + final_path + " keeps the previous one" : ""));
  }
}

Checkpoint read_checkpoint(const std::string& file) {
  return h5::naming_file(file, [&] {
    h5::Handle f = h5::open_file_read(file);
    if (!h5::exists(f, "checkpoint")) throw h5::Error(file + ": not a checkpoint (no /checkpoint group)");
    h5::Handle g = h5::open_group(f, "checkpoint");
    Checkpoint c;
    c.identity = h5::get_string_attribute(g, "identity");
    c.wall_time_s = finite_attribute(g, file, "wall_time_s");
    h5::Handle state = h5::open_group(g, "state");
    c.state = read_state(state, file);
    FieldReader from_state{state, file, c.state.particles.size()};
    list_fields(from_state, c.list, c.list_history);
    energy_fields(from_state, c.energy);
    const h5::Handle cursor_group = h5::open_group(g, "cursor");
    FieldReader from_cursor{cursor_group, file, 0};
    cursor_fields(from_cursor, c.cursor);
    // Last, so that a value out of range is named as such; any other change is caught here.
    if (!h5::has_attribute(g, "checksum")) throw h5::Error(file + ": /checkpoint has no checksum (written before checksums)");
    const std::string recorded = h5::get_string_attribute(g, "checksum"), found = h5::digest(f, "checkpoint", "checksum");
    if (found != recorded)
      throw h5::Error(file + ": checksum " + found + " differs from the one written with it, " + recorded +
                      ": the checkpoint was changed after it was written (an edit or a damaged disk)");
    return c;
  });
}

// The identity (scene, engine, particle file) and the stage were checked by the caller.
Simulation restore_simulation(const SceneConfig& scene, Checkpoint& c) {
  Simulation sim(std::move(c.state.particles), c.state.cell, scene.material, scene.damping, scene.time_step_s,
                 scene.verlet_skin_m);
  sim.restore_checkpoint(c.state.step, c.state.rates, std::move(c.list), c.list_history, c.energy);
  return sim;
}

}  // namespace dem
