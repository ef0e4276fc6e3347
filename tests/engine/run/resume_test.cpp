// Bit-for-bit continuation from a saved state (engine/io/state_io.hpp: "everything needed to
// continue a run bit for bit"). A two-stage scene run in one go must end in exactly the same state
// (compared with ==, not approximately) as its first stage written to a result file, followed by
// a second scene that starts from that file (`particles: {state: first.h5}`) and runs the second
// stage. The continuation starts its own step count at 0, so states are compared, not steps.
//
// Why exact equality is the right expectation: a step is a deterministic function of the
// positions, velocities, spins, cell, applied strain rate and contact springs, all stored as
// doubles (HDF5 native double, no conversion); forces are summed over pairs sorted by (i, j) in
// chunks by particle, so the Verlet list the continuation builds (with other non-contact pairs)
// does not change any sum (tests/engine/dynamics/skin_test.cpp). Checkpoints store the whole list
// (tests/engine/run/checkpoint_test.cpp, tests/kill/).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "analysis/measurements.hpp"
#include "config/scene_config.hpp"
#include "engine/dynamics/packing_support.hpp"
#include "engine/io/io_test_support.hpp"
#include "io/hdf5.hpp"
#include "io/state_io.hpp"
#include "run/run_scene.hpp"

using namespace dem;
using dem::test::touching;

namespace {

struct Variant {
  std::string name;
  std::string material;  // YAML flow mapping
  std::string damping;   // YAML flow mapping
  std::string second_stage;
  bool second_stage_fails = false;  // a stress stage that times out: the states at the failure are compared
};

// 64 spheres of 4 ... 4.5 mm on a 4x4x4 lattice of spacing 4.5 mm (an 18 mm cube): neighbours
// are at most 0.5 mm apart, so 4 % isotropic compression (stage "compress", 20/s for 2 ms)
// presses most neighbours into contact. dt = 2 us (0.2 x critical is ~3.8 us for a 4 mm sphere).
std::string scene_text(const Variant& v, const std::string& particles, bool first, bool second) {
  std::string s = "name: resume_" + v.name + "\n" + particles +
                  "material: " + v.material + "\n"
                  "damping: " + v.damping + "\n"
                  "numerics: {time_step: 2.0e-6}\n"
                  "output: {interval: 100}\n"
                  "stages:\n";
  if (first) s += "  - {name: compress, type: strain_rate, strain_rate: [20, 20, 20], duration: 2.0e-3}\n";
  if (second) s += v.second_stage;
  return s;
}

const std::string lattice =
    "particles:\n"
    "  lattice: {n: [4, 4, 4], spacing: 4.5e-3, seed: 3}\n"
    "  grading: {diameters: [4.0e-3, 4.5e-3], percent_finer: [0, 100]}\n";


// Every difference between two states, compared with == (empty: identical bit for bit, up to
// the sign of zero).
std::string differences(const Simulation& a, const Simulation& b) {
  std::ostringstream d;
  const Particles &pa = a.particles(), &pb = b.particles();
  if (pa.size() != pb.size()) return "particle counts differ";
  int n_diff = 0;
  for (std::size_t i = 0; i < pa.size(); ++i) {
    const bool same = pa.s[i] == pb.s[i] && pa.v[i] == pb.v[i] && pa.omega[i] == pb.omega[i] &&
                      pa.radius[i] == pb.radius[i] && pa.mass[i] == pb.mass[i] && pa.inertia[i] == pb.inertia[i];
    if (!same && n_diff++ == 0) {
      d.precision(17);
      d << "particle " << i << ": s " << pa.s[i].transpose() << " vs " << pb.s[i].transpose() << "; v "
        << pa.v[i].transpose() << " vs " << pb.v[i].transpose() << "\n";
    }
  }
  if (n_diff) d << n_diff << " particles differ\n";
  if (a.cell().lengths() != b.cell().lengths()) d << "cell lengths differ\n";
  if (a.cell().reference_lengths() != b.cell().reference_lengths()) d << "reference lengths differ\n";
  if (a.strain_rate() != b.strain_rate()) d << "strain rates differ\n";
  if (touching(a) != touching(b)) d << "contacts or their springs differ\n";
  if (a.sums().stress_Pa != b.sums().stress_Pa) d << "stresses differ\n";
  if (a.kinetic_energy() != b.kinetic_energy()) d << "kinetic energies differ\n";
  return d.str();
}

struct StageRecord {
  std::size_t min_contacts = static_cast<std::size_t>(-1), max_sliding = 0, rows = 0;
  std::size_t list_builds = 0;  // Verlet list rebuilds during the stage
};

// Runs stage `index` of `scene`, recording contacts at every row (including the row every
// stage writes at its start, before its first step); a stage expected to fail must throw
// StageError (and then the state at the failure is what gets compared). Contacts are counted
// from the state (count_contacts), not from the last step's sums: a run built from a saved state
// has made no step when its first row is taken.
StageRecord run_recorded(Simulation& sim, const SceneConfig& scene, int index, bool fails) {
  StageRecord r;
  StageHooks hooks;
  hooks.row = [&](const Simulation& s, const RowContext&) {
    r.min_contacts = std::min(r.min_contacts, count_contacts(s).contacts);
    std::size_t sliding = 0;
    for (auto f : s.history().sliding) sliding += f;
    r.max_sliding = std::max(r.max_sliding, sliding);
    ++r.rows;
  };
  const std::size_t builds_before = sim.verlet_list().builds();
  if (fails)
    REQUIRE_THROWS_AS(run_stage(sim, scene, index, hooks), StageError);
  else
    run_stage(sim, scene, index, hooks);
  r.list_builds = sim.verlet_list().builds() - builds_before;
  return r;
}

// Adds `dv` to the x velocity of particle 0 in the /state of a result file.
void perturb_velocity(const std::string& file, double dv) {
  h5::Handle f = h5::open_file_write(file);
  h5::Handle ds(H5Dopen2(f, "state/velocity", H5P_DEFAULT));
  REQUIRE(ds.id() >= 0);
  std::vector<double> v(static_cast<std::size_t>(H5Sget_simple_extent_npoints(h5::Handle(H5Dget_space(ds)))));
  REQUIRE(H5Dread(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) >= 0);
  v[0] += dv;
  REQUIRE(H5Dwrite(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) >= 0);
}

void check_resume(const Variant& v) {
  const std::string dir = test::scratch_dir("resume_" + v.name);
  const AnyContactLaw law = scene_from_text(scene_text(v, lattice, true, true), "x.yaml").material.law;
  const bool friction = has_tangential(law), rolling = has_rolling(law);

  // Uninterrupted: both stages on one simulation.
  const SceneConfig both = scene_from_text(scene_text(v, lattice, true, true), dir + "/both.yaml");
  Simulation full = build_simulation(both);
  const StageRecord first_stage = run_recorded(full, both, 0, false);
  const std::int64_t steps_first = full.step_count();
  const StageRecord second_full = run_recorded(full, both, 1, v.second_stage_fails);

  // Interrupted: the first stage alone, written to a result file ...
  const SceneConfig first = scene_from_text(scene_text(v, lattice, true, false), dir + "/first.yaml");
  run_scene(first, dir + "/first.h5");
  // ... and the second stage from its final state (relative path: resolved against the scene folder).
  const SceneConfig rest = scene_from_text(scene_text(v, "particles: {state: first.h5}\n", false, true), dir + "/rest.yaml");
  Simulation resumed = build_simulation(rest);
  CHECK(resumed.step_count() == 0);  // a new run counts its own steps
  const StageRecord second_resumed = run_recorded(resumed, rest, 0, v.second_stage_fails);

  // The test can only fail if the second stage has work to do: contacts all along (and, with
  // friction, contacts at the Coulomb limit, whose sliding flags must be carried over too).
  INFO("first stage: " << steps_first << " steps, min contacts " << first_stage.min_contacts);
  INFO("second stage: " << second_full.rows << " rows, min contacts " << second_full.min_contacts << ", max sliding "
                        << second_full.max_sliding << ", list builds " << second_full.list_builds << " (uninterrupted) / "
                        << second_resumed.list_builds << " (resumed)");
  REQUIRE(second_full.rows >= 5);
  REQUIRE(second_full.min_contacts > 0);
  if (friction) REQUIRE(second_full.max_sliding > 0);
  if (rolling) {  // rolling springs loaded, some at their cap (the energy it took), at the end of the stage
    REQUIRE(full.energy().dissipated_rolling > 0);
    std::size_t loaded = 0;
    for (const auto& c : touching(full)) loaded += std::get<4>(c) != Vec3::Zero();
    REQUIRE(loaded > 0);
  }
  // The list is rebuilt during the stage (the resumed run also at its first step), so the two
  // runs sum forces over lists built at different times: the claim of verlet_list.hpp that
  // results do not depend on when the list was rebuilt is exercised.
  REQUIRE(second_full.list_builds >= 1);
  CHECK(second_resumed.min_contacts == second_full.min_contacts);
  CHECK(second_resumed.rows == second_full.rows);

  CHECK(resumed.step_count() == full.step_count() - steps_first);
  const std::string diff = differences(full, resumed);
  INFO(diff);
  CHECK(diff.empty());

  // Control: the comparison is sensitive. The same continuation from a state whose one velocity
  // component is off by 1e-10 m/s must end in a different state. (A much smaller change can
  // vanish legitimately: 1e-15 m/s moves a sphere by 1e-15 x dt / L ~ 1e-19 of the cell per step,
  // far below the resolution of s ~ 0.5 (1.1e-16), and the damping then removes it from the
  // velocity; this happened in the frictionless variant. 1e-10 m/s moves it by ~1e-14 per step.)
  std::filesystem::copy_file(dir + "/first.h5", dir + "/perturbed.h5");
  perturb_velocity(dir + "/perturbed.h5", 1e-10);
  const SceneConfig rest_perturbed =
      scene_from_text(scene_text(v, "particles: {state: perturbed.h5}\n", false, true), dir + "/rest_perturbed.yaml");
  Simulation perturbed = build_simulation(rest_perturbed);
  run_recorded(perturbed, rest_perturbed, 0, v.second_stage_fails);
  CHECK_FALSE(differences(full, perturbed).empty());
}

// The same comparison through the result files alone (what a user does with `dem run` twice):
// the /state of the two-stage run equals the /state of the continued run.
void check_resume_files(const Variant& v) {
  const std::string dir = test::scratch_dir("resume_files_" + v.name);
  run_scene(scene_from_text(scene_text(v, lattice, true, true), dir + "/both.yaml"), dir + "/both.h5");
  run_scene(scene_from_text(scene_text(v, lattice, true, false), dir + "/first.yaml"), dir + "/first.h5");
  run_scene(scene_from_text(scene_text(v, "particles: {state: first.h5}\n", false, true), dir + "/rest.yaml"),
            dir + "/rest.h5");
  const SavedState a = read_state(dir + "/both.h5"), b = read_state(dir + "/rest.h5");
  REQUIRE(a.contacts.size() > 0);
  CHECK(a.particles.s == b.particles.s);
  CHECK(a.particles.v == b.particles.v);
  CHECK(a.particles.omega == b.particles.omega);
  CHECK(a.particles.radius == b.particles.radius);
  CHECK(a.cell.lengths() == b.cell.lengths());
  CHECK(a.cell.reference_lengths() == b.cell.reference_lengths());
  CHECK(a.rates.axial == b.rates.axial);
  CHECK(a.contacts.first == b.contacts.first);
  CHECK(a.contacts.second == b.contacts.second);
  CHECK(a.history.tangential_name == b.history.tangential_name);
  CHECK(a.history.tangential == b.history.tangential);
  CHECK(a.history.sliding == b.history.sliding);
  CHECK(a.history.rolling_on == b.history.rolling_on);
  CHECK(a.history.rolling == b.history.rolling);
  // The step counts differ by the first stage's steps (1000 steps of 2 us).
  CHECK(a.step - b.step == 1000);

  // The time series of the continued run repeats the uninterrupted run's rows from the start of
  // the second stage on (rows every 100 steps; the first stage has 1000 steps, so the rows
  // align): every measured column bit for bit. Not compared: step, time and stage (the continued
  // run counts from 0), the Verlet list build count, and in the continued run's first row, taken
  // before its first step, unbalanced_force_ratio, which needs the net forces of a force
  // evaluation (without one the engine reports 1; see the report of this test suite), and the
  // energy balance taken from the last force evaluation (elastic and centred kinetic energy). The
  // cumulative energy columns count from each run's own first step, so they are not compared.
  h5::Handle fa = h5::open_file_read(dir + "/both.h5"), fb = h5::open_file_read(dir + "/rest.h5");
  h5::Handle ga = h5::open_group(fa, "timeseries"), gb = h5::open_group(fb, "timeseries");
  std::size_t cols = 0;
  const auto steps_a = h5::read<double>(ga, "step", cols), steps_b = h5::read<double>(gb, "step", cols);
  // Every stage writes a row at its start and at its end: 11 rows (steps 0 ... 1000) for the
  // first stage, then 26 rows (1000 again, at the second stage's start, ... 3500).
  REQUIRE(steps_a.size() == 37);
  REQUIRE(steps_b.size() == 26);  // steps 0 ... 2500
  REQUIRE(steps_a[10] == 1000);
  REQUIRE(steps_a[11] == 1000);
  const auto stage_a = h5::read<double>(ga, "stage", cols);
  CHECK(stage_a[10] == 0);
  CHECK(stage_a[11] == 1);
  for (const std::string& name : test::h5_members(ga)) {
    if (name == "step" || name == "time" || name == "stage" || name == "neighbour_list_builds" ||
        name == "work_by_cell" || name.rfind("dissipated_by_", 0) == 0 || name == "energy_closure_error")
      continue;
    const auto ya = h5::read<double>(ga, name, cols), yb = h5::read<double>(gb, name, cols);
    const bool needs_a_step = name == "unbalanced_force_ratio" || name.rfind("elastic_energy_", 0) == 0 ||
                              name == "kinetic_energy_centred";
    for (std::size_t k = needs_a_step ? 1 : 0; k < yb.size(); ++k) {
      INFO("column " << name << ", continued row " << k);
      CHECK(ya[11 + k] == yb[k]);
    }
  }
}

// Second stage: 5 ms of shear at constant volume rate (compress axis 1 by 10 %, extend 2 and 3).
const std::string shear = "  - {name: shear, type: strain_rate, strain_rate: [20, -10, -10], duration: 5.0e-3, reset_strain: true}\n";

}  // namespace

TEST_CASE("resume: a frictional two-stage run continues bit for bit from its saved state", "[run][resume]") {
  check_resume({"frictional", "{kn: 1.0e6, ks: 1.0e6, friction: 0.5}", "{form: viscous}", shear});
}

TEST_CASE("resume: a frictionless two-stage run continues bit for bit from its saved state", "[run][resume]") {
  check_resume({"frictionless", "{kn: 1.0e6, ks: 1.0e6, friction: 0}", "{form: viscous}", shear});
}

TEST_CASE("resume: local damping and a stress stage continue bit for bit", "[run][resume]") {
  // The stress stage starts from the stress measured on the restored state and drives the cell
  // with the servo; it cannot reach equilibrium in 1 ms, so both runs stop with StageError at
  // the same step, and the states there are compared.
  check_resume({"stress", "{kn: 1.0e6, ks: 1.0e6, friction: 0.3}", "{form: local, translational: 0.3, rotational: 0.3}",
                "  - {name: unload, type: stress, target: [1.0e5, 1.0e5, 1.0e5], rate: 1.0e9, max_strain_rate: 5,\n"
                "     hold: {max_duration: 1.0e-3, check_interval: 50}}\n",
                true});
}

TEST_CASE("resume: the result files of a run in one go and of a continued run have the same /state", "[run][resume][io]") {
  check_resume_files({"frictional", "{kn: 1.0e6, ks: 1.0e6, friction: 0.5}", "{form: viscous}", shear});
  check_resume_files({"frictionless", "{kn: 1.0e6, ks: 1.0e6, friction: 0}", "{form: viscous}", shear});
}

// Hertz-Mindlin with rolling resistance: the history is the tangential force itself
// (contact_tangential_force [N]) and a rolling spring (contact_rolling_spring [m]), both in /state.
// E = 1e9 Pa, nu = 0.3: the Rayleigh step for the 4 mm spheres is 17.8 us, dt = 2 us is 0.11 of it.
const Variant hertz_mindlin_rolling{"hertz_mindlin_rolling",
                                    "{law: hertz_mindlin, young_modulus: 1.0e9, poisson_ratio: 0.3, friction: 0.5, "
                                    "rolling_friction: 0.1, rolling_stiffness: 5.0e4}",
                                    "{form: local, translational: 0.1, rotational: 0.1}", shear};

TEST_CASE("resume: a Hertz-Mindlin run with rolling resistance continues bit for bit from its saved state", "[run][resume][law]") {
  check_resume(hertz_mindlin_rolling);
}

TEST_CASE("resume: the /state of a Hertz-Mindlin run with rolling resistance holds its histories and continues bit for bit",
          "[run][resume][io][law]") {
  check_resume_files(hertz_mindlin_rolling);
  // The histories the saved state must carry, by their names in the file.
  const std::string file = std::string(DEM_BINARY_DIR) + "/test_tmp/resume_files_hertz_mindlin_rolling/first.h5";  // check_resume_files wrote it
  h5::Handle f = h5::open_file_read(file);
  h5::Handle state = h5::open_group(f, "state");
  CHECK(h5::exists(state, "contact_tangential_force"));
  CHECK(h5::exists(state, "contact_rolling_spring"));
  CHECK_FALSE(h5::exists(state, "contact_tangential_spring"));
  const SavedState st = read_state(file);
  REQUIRE(st.contacts.size() > 0);
  CHECK(st.history.tangential_name == "tangential_force");
  std::size_t loaded = 0;
  for (const Vec3& r : st.history.rolling) loaded += r != Vec3::Zero();
  CHECK(loaded > 0);
}

TEST_CASE("the first row of a continued run reports the saved state's kinetic energy and inertial number",
          "[run][resume]") {
  // Both are functions of the state: kinetic_energy_translational is "of the fluctuating
  // velocities", the inertial number uses the row's mean stress p and the last applied strain
  // rate, which a run built from a saved state takes from the file. So the continued run's first
  // row (before any step) equals the last row of the earlier run, which holds the same state.
  const std::string dir = test::scratch_dir("resume_first_row");
  const Variant v{"frictional", "{kn: 1.0e6, ks: 1.0e6, friction: 0.5}", "{form: viscous}", shear};
  run_scene(scene_from_text(scene_text(v, lattice, true, false), dir + "/first.yaml"), dir + "/first.h5");
  run_scene(scene_from_text(scene_text(v, "particles: {state: first.h5}\n", false, true), dir + "/rest.yaml"),
            dir + "/rest.h5");
  h5::Handle fa = h5::open_file_read(dir + "/first.h5"), fb = h5::open_file_read(dir + "/rest.h5");
  h5::Handle ga = h5::open_group(fa, "timeseries"), gb = h5::open_group(fb, "timeseries");
  std::size_t cols = 0;
  const auto ea = h5::read<double>(ga, "kinetic_energy_translational", cols);
  const auto eb = h5::read<double>(gb, "kinetic_energy_translational", cols);
  REQUIRE(ea.back() > 0);
  CHECK(eb.front() == ea.back());
  const auto ia = h5::read<double>(ga, "inertial_number", cols);
  const auto ib = h5::read<double>(gb, "inertial_number", cols);
  REQUIRE(ia.back() > 0);
  CHECK(ib.front() == ia.back());
  // Independently: I = max|rate| d_mean sqrt(rho / p) with the saved strain rate (20/s on every
  // axis in the first stage), the row's p and the mean diameter of the saved particles.
  const SavedState st = read_state(dir + "/first.h5");
  double d_mean = 0;
  for (double r : st.particles.radius) d_mean += 2 * r;
  d_mean /= static_cast<double>(st.particles.size());
  const double p = h5::read<double>(gb, "p", cols).front();
  REQUIRE(st.rates.axial.cwiseAbs().maxCoeff() == Approx(20).epsilon(1e-12));
  CHECK(ib.front() == Approx(st.rates.axial.cwiseAbs().maxCoeff() * d_mean * std::sqrt(2650 / p)).epsilon(1e-12));
  // ... and the kinetic energy sum 1/2 m v^2 over the saved velocities.
  double e = 0;
  for (std::size_t i = 0; i < st.particles.size(); ++i) e += 0.5 * st.particles.mass[i] * st.particles.v[i].squaredNorm();
  CHECK(eb.front() == Approx(e).epsilon(1e-12));
}
