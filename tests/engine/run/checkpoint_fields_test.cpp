// The fields of a checkpoint (engine/run/checkpoint.cpp: list_fields, energy_fields,
// cursor_fields, each field named once with how it is stored): what is written is read back
// exactly, under the names and in the form checkpoints have always had, so that a checkpoint of an
// earlier build still reads. checkpoint_test.cpp resumes whole runs from checkpoints; this checks
// every field on its own, each set to a value of its own so that two swapped fields would show.
#include <catch2/catch.hpp>

#include <set>
#include <string>
#include <vector>

#include "config/scene_config.hpp"
#include "engine/io/io_test_support.hpp"
#include "io/hdf5.hpp"
#include "run/checkpoint.hpp"
#include "run/run_scene.hpp"

using namespace dem;

namespace {

std::set<std::string> attribute_names(hid_t obj) {
  std::set<std::string> names;
  H5Aiterate2(obj, H5_INDEX_NAME, H5_ITER_INC, nullptr,
              [](hid_t, const char* name, const H5A_info_t*, void* out) -> herr_t {
                static_cast<std::set<std::string>*>(out)->insert(name);
                return 0;
              },
              &names);
  return names;
}

std::string units_of(hid_t group, const std::string& name) {
  h5::Handle ds(H5Dopen2(group, name.c_str(), H5P_DEFAULT));
  REQUIRE(ds.id() >= 0);
  return h5::get_string_attribute(ds, h5::unit_attribute);
}

// 64 spheres of 4.0-4.5 mm at 4.5 mm (a frictional linear law: tangential springs, sliding flags)
// squeezed at 20/s and sheared xy at 20/s for 1,500 steps (3 %): contacts, a tilted cell and a shear
// stress (so the fields written only when not zero are written) and a started energy balance.
Simulation sheared_simulation(const std::string& dir) {
  const SceneConfig scene = scene_from_text(
      "name: fields\n"
      "particles:\n"
      "  lattice: {n: [4, 4, 4], spacing: 4.5e-3, seed: 3}\n"
      "  grading: {diameters: [4.0e-3, 4.5e-3], percent_finer: [0, 100]}\n"
      "material: {kn: 1.0e6, ks: 1.0e6, friction: 0.5}\n"
      "numerics: {time_step: 1.0e-6}\n"
      "stages:\n"
      "  - {name: squeeze, type: strain_rate, strain_rate: [20, 20, 20], duration: 1.5e-3}\n",
      dir + "/s.yaml");
  Simulation sim = build_simulation(scene);
  CellControl control;
  for (std::size_t k = 0; k < 3; ++k) control.component[k] = {AxisTarget::Mode::StrainRate, 20, 0, 0};
  control.component[3] = {AxisTarget::Mode::StrainRate, 20, 0, 0};
  for (int step = 0; step < 1500; ++step) sim.step(control, scene.servo);
  return sim;
}

}  // namespace

TEST_CASE("every checkpoint field is read back as written, under its established name", "[run][checkpoint]") {
  const std::string dir = test::scratch_dir("checkpoint_fields");
  const Simulation sim = sheared_simulation(dir);
  REQUIRE(sim.history().tangential.size() == sim.verlet_list().pairs().size());
  REQUIRE(sim.verlet_list().pairs().size() > 0);
  REQUIRE(sim.cell().tilts() != Vec3::Zero());
  REQUIRE(sim.energy().shear_virial != Vec3::Zero());
  REQUIRE(sim.energy().started);

  StageCursor c;  // every field a value of its own
  c.stage = 2, c.i = 1234, c.leg = 3, c.done_steps = 4321;
  c.from_Pa = Vec3(1.5e5, 2.5e5, 3.5e5);
  c.stress_error = 0.0125, c.unbalanced = 0.03;
  c.creep_window_start = 777, c.creep_volume_at_start = 3.3e-6, c.creep_rate = 4e-3;
  c.servo.kappa = Vec3(0.9, 1.1, 1.2), c.servo.predicted = Vec3(1e5, 1.1e5, 1.2e5);
  c.servo.window_start = Vec3(2e5, 2.1e5, 2.2e5), c.servo.steps = 17, c.servo.kappa_shear = 0.7;
  c.servo.predicted_shear = Vec3(10, 20, 30), c.servo.window_start_shear = Vec3(40, 50, 60);
  c.sum_sq = Vec3(1e6, 2e6, 3e6), c.max_inertial_number = 2e-4, c.strain_at_leg_start = Vec3(1e-3, 2e-3, 3e-3);
  c.mean_stress_at_start = 1e5, c.deviator_at_start = 2e4;
  c.strain_at_start = {1e-4, 2e-4, 3e-4, 4e-4, 5e-4, 6e-4};
  c.cycle_low = -1e-3, c.cycle_high = 2e-3;

  const std::string out = dir + "/r.h5";
  {
    h5::Handle partial = h5::create_file(out + ".partial");
    h5::close_file(partial, out + ".partial");
  }
  write_checkpoint(out + ".partial", out, "identity", 12.5, sim, c);
  const Checkpoint back = read_checkpoint(checkpoint_path(out));

  SECTION("the values") {
    CHECK(back.identity == "identity");
    CHECK(back.wall_time_s == 12.5);
    const StageCursor& r = back.cursor;
    CHECK(r.stage == c.stage);
    CHECK(r.i == c.i);
    CHECK(r.leg == c.leg);
    CHECK(r.done_steps == c.done_steps);
    CHECK(r.from_Pa == c.from_Pa);
    CHECK(r.stress_error == c.stress_error);
    CHECK(r.unbalanced == c.unbalanced);
    CHECK(r.creep_window_start == c.creep_window_start);
    CHECK(r.creep_volume_at_start == c.creep_volume_at_start);
    CHECK(r.creep_rate == c.creep_rate);
    CHECK(r.servo.kappa == c.servo.kappa);
    CHECK(r.servo.predicted == c.servo.predicted);
    CHECK(r.servo.window_start == c.servo.window_start);
    CHECK(r.servo.steps == c.servo.steps);
    CHECK(r.servo.kappa_shear == c.servo.kappa_shear);
    CHECK(r.servo.predicted_shear == c.servo.predicted_shear);
    CHECK(r.servo.window_start_shear == c.servo.window_start_shear);
    CHECK(r.sum_sq == c.sum_sq);
    CHECK(r.max_inertial_number == c.max_inertial_number);
    CHECK(r.strain_at_leg_start == c.strain_at_leg_start);
    CHECK(r.mean_stress_at_start == c.mean_stress_at_start);
    CHECK(r.deviator_at_start == c.deviator_at_start);
    CHECK(r.strain_at_start == c.strain_at_start);
    CHECK(r.cycle_low == c.cycle_low);
    CHECK(r.cycle_high == c.cycle_high);

    const EnergyBalance &e = sim.energy(), &f = back.energy;
    CHECK(f.work_by_cell == e.work_by_cell);
    CHECK(f.dissipated_damping == e.dissipated_damping);
    CHECK(f.dissipated_friction == e.dissipated_friction);
    CHECK(f.dissipated_rolling == e.dissipated_rolling);
    CHECK(f.kinetic == e.kinetic);
    CHECK(f.elastic == e.elastic);
    CHECK(f.stored_at_start == e.stored_at_start);
    CHECK(f.virial == e.virial);
    CHECK(f.shear_virial == e.shear_virial);
    CHECK(f.started == e.started);

    const VerletList::Saved list = sim.verlet_list().saved();
    CHECK(back.list.pairs.first == list.pairs.first);
    CHECK(back.list.pairs.second == list.pairs.second);
    CHECK(back.list.s_at_build == list.s_at_build);
    CHECK(back.list.lengths_at_build == list.lengths_at_build);
    CHECK(back.list.tilts_at_build == list.tilts_at_build);
    CHECK(back.list.builds == list.builds);
    CHECK(back.list_history.tangential == sim.history().tangential);
    CHECK(back.list_history.sliding == sim.history().sliding);
  }
  SECTION("the names and units on disk") {
    h5::Handle f = h5::open_file_read(checkpoint_path(out));
    h5::Handle cursor = h5::open_group(f, "checkpoint/cursor");
    CHECK(attribute_names(cursor) ==
          std::set<std::string>{"stage", "iteration", "leg", "done_steps", "stress_error", "unbalanced", "creep_window_start",
                                "creep_volume_at_start", "creep_rate", "max_inertial_number", "servo_steps", "servo_kappa_shear",
                                "mean_stress_at_start", "deviator_at_start", "cycle_low", "cycle_high"});
    const std::vector<std::string> members = test::h5_members(cursor);
    CHECK(std::set<std::string>(members.begin(), members.end()) ==
          std::set<std::string>{"from", "sum_sq", "strain_at_leg_start", "servo_kappa", "servo_predicted", "servo_window_start",
                                "servo_predicted_shear", "servo_window_start_shear", "strain_at_start"});
    CHECK(units_of(cursor, "from") == "Pa");
    CHECK(units_of(cursor, "sum_sq") == "Pa^2");
    CHECK(units_of(cursor, "servo_kappa") == "1");
    CHECK(units_of(cursor, "strain_at_start") == "1");
    std::size_t cols = 0;
    CHECK(h5::read<double>(cursor, "strain_at_start", cols).size() == 6);
    CHECK(h5::get_int_attribute(cursor, "iteration") == 1234);

    h5::Handle state = h5::open_group(f, "checkpoint/state");
    const std::set<std::string> attributes = attribute_names(state);
    for (const char* name : {"energy_work_by_cell", "energy_dissipated_damping", "energy_dissipated_friction",
                             "energy_dissipated_rolling", "energy_kinetic", "energy_elastic", "energy_stored_at_start",
                             "energy_started", "verlet_builds"}) {
      INFO(name);
      CHECK(attributes.count(name) == 1);
    }
    CHECK(units_of(state, "energy_virial") == "J");
    CHECK(units_of(state, "energy_shear_virial") == "J");
    CHECK(units_of(state, "verlet_position_fractional_at_build") == "1");
    CHECK(units_of(state, "verlet_cell_lengths_at_build") == "m");
    CHECK(units_of(state, "verlet_cell_tilts_at_build") == "m");
    CHECK(h5::read<double>(state, "verlet_position_fractional_at_build", cols).size() == 3 * sim.particles().size());
    CHECK(cols == 3);
    for (const char* name : {"verlet_first", "verlet_second", "verlet_tangential_spring", "verlet_sliding"}) {
      INFO(name);
      CHECK(h5::exists(state, name));
    }
  }
}
