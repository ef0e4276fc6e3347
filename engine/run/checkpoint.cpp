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

void write_vec3(hid_t g, const std::string& name, const Vec3& v, const std::string& units) {
  h5::write(g, name, std::vector<double>{v[0], v[1], v[2]}, 1, units);
}

Vec3 read_one_vec3(hid_t g, const std::string& file, const std::string& name) {
  std::size_t cols = 0;
  const std::vector<double> d = h5::read<double>(g, name, cols);
  if (d.size() != 3 || !std::isfinite(d[0]) || !std::isfinite(d[1]) || !std::isfinite(d[2]))
    throw h5::Error(file + ": /checkpoint: " + name + " must be 3 finite values");
  return {d[0], d[1], d[2]};
}

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

void write_list(hid_t g, const VerletList::Saved& list, const ContactHistory& history) {
  write_pairs(g, "verlet", list.pairs, history);
  h5::write(g, "verlet_position_fractional_at_build", flatten(list.s_at_build), 3, "1");
  write_vec3(g, "verlet_cell_lengths_at_build", list.lengths_at_build, "m");
  if (list.tilts_at_build != Vec3::Zero()) write_vec3(g, "verlet_cell_tilts_at_build", list.tilts_at_build, "m");
  h5::set_attribute(g, "verlet_builds", static_cast<std::int64_t>(list.builds));
}

VerletList::Saved read_list(hid_t g, const std::string& file, std::size_t n, ContactHistory& history) {
  VerletList::Saved list;
  SavedPairs pairs = read_pairs(g, file, "verlet", n);
  list.pairs = std::move(pairs.pairs);
  history = std::move(pairs.history);
  list.s_at_build = read_vec3(g, file, "verlet_position_fractional_at_build");
  list.lengths_at_build = read_one_vec3(g, file, "verlet_cell_lengths_at_build");
  if (h5::exists(g, "verlet_cell_tilts_at_build")) list.tilts_at_build = read_one_vec3(g, file, "verlet_cell_tilts_at_build");
  list.builds = static_cast<std::size_t>(int_attribute(g, file, "verlet_builds", 0, std::numeric_limits<std::int64_t>::max()));
  if (list.s_at_build.size() != n)
    throw h5::Error(file + ": /checkpoint/state: verlet_position_fractional_at_build has " +
                    std::to_string(list.s_at_build.size()) + " rows for " + std::to_string(n) + " particles");
  for (const Vec3& s : list.s_at_build)
    if (!s.allFinite()) throw h5::Error(file + ": /checkpoint/state: a non-finite position at the last list build");
  return list;
}

// The energy balance: one attribute per accumulated quantity.
void write_energy(hid_t g, const EnergyBalance& e) {
  h5::set_attribute(g, "energy_work_by_cell", e.work_by_cell);
  h5::set_attribute(g, "energy_dissipated_damping", e.dissipated_damping);
  h5::set_attribute(g, "energy_dissipated_friction", e.dissipated_friction);
  h5::set_attribute(g, "energy_dissipated_rolling", e.dissipated_rolling);
  h5::set_attribute(g, "energy_kinetic", e.kinetic);
  h5::set_attribute(g, "energy_elastic", e.elastic);
  h5::set_attribute(g, "energy_stored_at_start", e.stored_at_start);
  h5::set_attribute(g, "energy_started", static_cast<std::int64_t>(e.started));
  write_vec3(g, "energy_virial", e.virial, "J");
  if (e.shear_virial != Vec3::Zero()) write_vec3(g, "energy_shear_virial", e.shear_virial, "J");
}

EnergyBalance read_energy(hid_t g, const std::string& file) {
  EnergyBalance e;
  e.work_by_cell = finite_attribute(g, file, "energy_work_by_cell");
  e.dissipated_damping = finite_attribute(g, file, "energy_dissipated_damping");
  e.dissipated_friction = finite_attribute(g, file, "energy_dissipated_friction");
  e.dissipated_rolling = finite_attribute(g, file, "energy_dissipated_rolling");
  e.kinetic = finite_attribute(g, file, "energy_kinetic");
  e.elastic = finite_attribute(g, file, "energy_elastic");
  e.stored_at_start = finite_attribute(g, file, "energy_stored_at_start");
  e.started = int_attribute(g, file, "energy_started", 0, 1) == 1;
  e.virial = read_one_vec3(g, file, "energy_virial");
  if (h5::exists(g, "energy_shear_virial")) e.shear_virial = read_one_vec3(g, file, "energy_shear_virial");
  return e;
}

void write_cursor(hid_t g, const StageCursor& c) {
  h5::set_attribute(g, "stage", static_cast<std::int64_t>(c.stage));
  h5::set_attribute(g, "iteration", c.i);
  h5::set_attribute(g, "leg", static_cast<std::int64_t>(c.leg));
  h5::set_attribute(g, "done_steps", c.done_steps);
  h5::set_attribute(g, "stress_error", c.stress_error);
  h5::set_attribute(g, "unbalanced", c.unbalanced);
  h5::set_attribute(g, "creep_window_start", c.creep_window_start);
  h5::set_attribute(g, "creep_volume_at_start", c.creep_volume_at_start);
  h5::set_attribute(g, "creep_rate", c.creep_rate);
  h5::set_attribute(g, "max_inertial_number", c.max_inertial_number);
  h5::set_attribute(g, "servo_steps", static_cast<std::int64_t>(c.servo.steps));
  write_vec3(g, "from", c.from_Pa, "Pa");
  write_vec3(g, "sum_sq", c.sum_sq, "Pa^2");
  write_vec3(g, "strain_at_leg_start", c.strain_at_leg_start, "1");
  write_vec3(g, "servo_kappa", c.servo.kappa, "1");
  write_vec3(g, "servo_predicted", c.servo.predicted, "Pa");
  write_vec3(g, "servo_window_start", c.servo.window_start, "Pa");
  h5::set_attribute(g, "servo_kappa_shear", c.servo.kappa_shear);
  write_vec3(g, "servo_predicted_shear", c.servo.predicted_shear, "Pa");
  write_vec3(g, "servo_window_start_shear", c.servo.window_start_shear, "Pa");
  h5::set_attribute(g, "mean_stress_at_start", c.mean_stress_at_start);
  h5::set_attribute(g, "deviator_at_start", c.deviator_at_start);
  h5::set_attribute(g, "cycle_low", c.cycle_low);
  h5::set_attribute(g, "cycle_high", c.cycle_high);
  h5::write(g, "strain_at_start", std::vector<double>(c.strain_at_start.begin(), c.strain_at_start.end()), 1, "1");
}

StageCursor read_cursor(hid_t g, const std::string& file) {
  StageCursor c;
  c.stage = static_cast<int>(int_attribute(g, file, "stage", 0, 1 << 30));
  c.i = int_attribute(g, file, "iteration", 1, std::numeric_limits<std::int64_t>::max());
  c.leg = static_cast<int>(int_attribute(g, file, "leg", 0, 1 << 30));
  c.done_steps = int_attribute(g, file, "done_steps", 0, std::numeric_limits<std::int64_t>::max());
  c.stress_error = finite_attribute(g, file, "stress_error");
  c.unbalanced = finite_attribute(g, file, "unbalanced");
  c.creep_window_start = int_attribute(g, file, "creep_window_start", -1, std::numeric_limits<std::int64_t>::max());
  c.creep_volume_at_start = finite_attribute(g, file, "creep_volume_at_start");
  c.creep_rate = finite_attribute(g, file, "creep_rate");
  c.max_inertial_number = finite_attribute(g, file, "max_inertial_number");
  c.servo.steps = static_cast<int>(int_attribute(g, file, "servo_steps", -1, 1 << 30));
  c.from_Pa = read_one_vec3(g, file, "from");
  c.sum_sq = read_one_vec3(g, file, "sum_sq");
  c.strain_at_leg_start = read_one_vec3(g, file, "strain_at_leg_start");
  c.servo.kappa = read_one_vec3(g, file, "servo_kappa");
  c.servo.predicted = read_one_vec3(g, file, "servo_predicted");
  c.servo.window_start = read_one_vec3(g, file, "servo_window_start");
  c.servo.kappa_shear = finite_attribute(g, file, "servo_kappa_shear");
  c.servo.predicted_shear = read_one_vec3(g, file, "servo_predicted_shear");
  c.servo.window_start_shear = read_one_vec3(g, file, "servo_window_start_shear");
  c.mean_stress_at_start = finite_attribute(g, file, "mean_stress_at_start");
  c.deviator_at_start = finite_attribute(g, file, "deviator_at_start");
  c.cycle_low = finite_attribute(g, file, "cycle_low");
  c.cycle_high = finite_attribute(g, file, "cycle_high");
  std::size_t cols = 0;
  const std::vector<double> strains = h5::read<double>(g, "strain_at_start", cols);
  if (strains.size() != 6 || !std::all_of(strains.begin(), strains.end(), [](double e) { return std::isfinite(e); }))
    throw h5::Error(file + ": /checkpoint: strain_at_start must be 6 finite values");
  std::copy(strains.begin(), strains.end(), c.strain_at_start.begin());
  return c;
}

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
      write_list(state, sim.verlet_list().saved(), sim.history());
      write_energy(state, sim.energy());
      write_cursor(h5::create_group(g, "cursor"), cursor);
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
    c.list = read_list(state, file, c.state.particles.size(), c.list_history);
    c.energy = read_energy(state, file);
    c.cursor = read_cursor(h5::open_group(g, "cursor"), file);
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
