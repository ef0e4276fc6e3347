// Checkpoints and resuming (engine/run/checkpoint.hpp), through the `dem` command. The kill tests
// (tests/kill/*.sh, in ctest) kill real runs at random moments; these cases pin down what happens
// around them: a run that stops keeps its checkpoint, resuming from it repeats the rest of the run
// exactly, and a checkpoint of other inputs or a damaged one is never resumed.
#include <catch2/catch.hpp>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>
#include <filesystem>
#include <string>

#include "engine/io/io_test_support.hpp"
#include "analysis/time_series.hpp"
#include "io/hdf5.hpp"

namespace fs = std::filesystem;

namespace {

const std::string dem_exe = std::string(DEM_BINARY_DIR) + "/bin/dem";

dem::test::CommandResult dem_stderr(const std::string& args) {
  return dem::test::run_command("'" + dem_exe + "' " + args + " 2>&1 >/dev/null");
}

// 27 spheres squeezed for 600 steps, then a stress stage that cannot reach equilibrium in 200
// steps: the run stops (exit 1) after checkpoints at steps 100 ... 700, and keeps the last.
std::string stopping_scene() {
  return dem::test::tiny_scene(
      "  - {name: squeeze, type: strain_rate, strain_rate: [2, 2, 2], duration: 6.0e-4}\n"
      "  - {name: hold, type: stress, target: [1.0e5, 1.0e5, 1.0e5], rate: 1.0e9, hold: {max_duration: 2.0e-4}}\n",
      "{kn: 1.0e6, ks: 1.0e6, friction: 0.5}", "output: {interval: 50, checkpoint_interval: 100}\n");
}

std::vector<double> column(const std::string& file, const std::string& name) {
  dem::h5::Handle f = dem::h5::open_file_read(file);
  std::size_t cols = 0;
  return dem::h5::read<double>(f, "timeseries/" + name, cols);
}

std::int64_t checkpoint_step(const std::string& file) {
  dem::h5::Handle f = dem::h5::open_file_read(file);
  return dem::h5::get_int_attribute(dem::h5::open_group(f, "checkpoint"), "step");
}

// Runs DIR/s.yaml into DIR/r.h5, which must stop (exit 1) with its checkpoint at `step`; keeps the
// stopped run's result as DIR/first.h5 and returns that path.
std::string stop_at_checkpoint(const std::string& dir, std::int64_t step) {
  const std::string out = dir + "/r.h5";
  const auto first = dem_stderr("run '" + dir + "/s.yaml' --out '" + out + "'");
  INFO(first.out);
  REQUIRE(first.exit_code == 1);
  REQUIRE(fs::exists(out + ".checkpoint"));
  REQUIRE(checkpoint_step(out + ".checkpoint") == step);
  fs::copy_file(out + ".partial", dir + "/first.h5");
  return dir + "/first.h5";
}

// Resumes DIR/s.yaml from the checkpoint at `step` that stop_at_checkpoint left: it must stop
// again, and every time-series column must equal the stopped run's (rows up to the checkpoint come
// from it, the rest are computed again: all equal, none twice).
void resume_bit_for_bit(const std::string& dir, std::int64_t step) {
  const std::string out = dir + "/r.h5";
  const auto again = dem_stderr("run '" + dir + "/s.yaml' --out '" + out + "' --resume");
  CHECK(again.exit_code == 1);
  CHECK_THAT(again.out, Catch::Matchers::Contains("resuming from " + out + ".checkpoint at step " + std::to_string(step)));
  for (const dem::SeriesColumn& c : dem::series_columns()) {
    INFO(c.name);
    CHECK(column(out + ".partial", c.name) == column(dir + "/first.h5", c.name));
  }
}

}  // namespace

TEST_CASE("a stopped run keeps its checkpoint, and resuming repeats the rest exactly", "[run][checkpoint]") {
  const std::string dir = dem::test::scratch_dir("checkpoint_resume");
  dem::test::write_text(dir + "/s.yaml", stopping_scene());
  stop_at_checkpoint(dir, 700);  // the last between two steps before the stop at 800
  resume_bit_for_bit(dir, 700);
  CHECK(column(dir + "/r.h5.partial", "step").size() == 13 + 5);  // squeeze: steps 0, 50 ... 600; hold: 600, 650 ... 800
}

TEST_CASE("a Hertz-Mindlin run with rolling resistance resumes from its checkpoint bit for bit", "[run][checkpoint][law]") {
  // The same stop-and-resume as above for the law with the most history: the tangential force
  // and the rolling spring of every listed pair go into the checkpoint with the whole Verlet list.
  // 64 spheres of 4.0-4.5 mm at 4.5 mm (tests/engine/run/resume_test.cpp) squeezed 4 % in 2 ms
  // (1,000 steps of 2 us, 0.11 of the Rayleigh step), then a stress stage that cannot settle in
  // 1 ms: the run stops at step 1,500 with its checkpoint at 1,400. Every time-series column of the
  // resumed run equals the first run's, the tangential and rolling spring energies included.
  const std::string dir = dem::test::scratch_dir("checkpoint_resume_hertz_mindlin_rolling");
  dem::test::write_text(dir + "/s.yaml",
                        "name: hmr\n"
                        "particles:\n"
                        "  lattice: {n: [4, 4, 4], spacing: 4.5e-3, seed: 3}\n"
                        "  grading: {diameters: [4.0e-3, 4.5e-3], percent_finer: [0, 100]}\n"
                        "material: {law: hertz_mindlin, young_modulus: 1.0e9, poisson_ratio: 0.3, friction: 0.5,\n"
                        "           rolling_friction: 0.1, rolling_stiffness: 5.0e4}\n"
                        "damping: {form: local, translational: 0.1, rotational: 0.1}\n"
                        "numerics: {time_step: 2.0e-6}\n"
                        "output: {interval: 50, checkpoint_interval: 100}\n"
                        "stages:\n"
                        "  - {name: compress, type: strain_rate, strain_rate: [20, 20, 20], duration: 2.0e-3}\n"
                        "  - {name: unload, type: stress, target: [1.0e5, 1.0e5, 1.0e5], rate: 1.0e9, max_strain_rate: 5,\n"
                        "     hold: {max_duration: 1.0e-3, check_interval: 50}}\n");
  const std::string first = stop_at_checkpoint(dir, 1400);
  // The rows after the checkpoint have loaded tangential and rolling springs, and sliding contacts.
  const auto steps = column(first, "step");
  const auto rolling = column(first, "elastic_energy_rolling");
  const auto tangential = column(first, "elastic_energy_tangential");
  const auto sliding = column(first, "sliding_fraction");
  REQUIRE(steps.back() == 1500);
  REQUIRE(rolling.back() > 0);
  REQUIRE(tangential.back() > 0);
  REQUIRE(column(first, "dissipated_by_rolling").back() > 0);
  double most_sliding = 0;
  for (std::size_t k = 0; k < steps.size(); ++k)
    if (steps[k] > 1400) most_sliding = std::max(most_sliding, sliding[k]);
  REQUIRE(most_sliding > 0);

  resume_bit_for_bit(dir, 1400);
}

TEST_CASE("a checkpoint of other inputs or a damaged one is not resumed", "[run][checkpoint][input]") {
  const std::string dir = dem::test::scratch_dir("checkpoint_refused");
  dem::test::write_text(dir + "/s.yaml", stopping_scene());
  const std::string out = dir + "/r.h5", run = "run '" + dir + "/s.yaml' --out '" + out + "'";
  REQUIRE(dem_stderr(run).exit_code == 1);
  const std::string good = dir + "/good.checkpoint";
  fs::copy_file(out + ".checkpoint", good);

  SECTION("--resume without a checkpoint is bad input") {
    fs::remove(out + ".checkpoint");
    const auto r = dem_stderr(run + " --resume");
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.out, Catch::Matchers::Contains(out + ".checkpoint: no checkpoint to resume from"));
  }
  SECTION("other inputs: by default a warning and a fresh start; --resume refuses") {
    const std::string other = run + " --set material.kn=1.1e6";
    const auto refused = dem_stderr(other + " --resume");
    CHECK(refused.exit_code == 2);
    CHECK_THAT(refused.out, Catch::Matchers::Contains("cannot resume: " + out + ".checkpoint: written by a run of other inputs"));
    const auto fresh = dem_stderr(other);
    CHECK(fresh.exit_code == 1);  // the same stop, from the beginning
    CHECK_THAT(fresh.out, Catch::Matchers::Contains("warning: not resuming: " + out + ".checkpoint: written by a run of other inputs"));
    CHECK_THAT(fresh.out, !Catch::Matchers::Contains("resuming from"));
  }
  SECTION("a truncated checkpoint") {
    fs::resize_file(out + ".checkpoint", fs::file_size(out + ".checkpoint") / 2);
    const auto refused = dem_stderr(run + " --resume");
    CHECK(refused.exit_code == 2);
    CHECK_THAT(refused.out, Catch::Matchers::Contains("cannot resume: " + out + ".checkpoint"));
    const auto fresh = dem_stderr(run);
    CHECK(fresh.exit_code == 1);
    CHECK_THAT(fresh.out, Catch::Matchers::Contains("warning: not resuming: " + out + ".checkpoint"));
  }
  SECTION("a result file is not a checkpoint") {
    fs::copy_file(out + ".partial", out + ".checkpoint", fs::copy_options::overwrite_existing);
    const auto refused = dem_stderr(run + " --resume");
    CHECK(refused.exit_code == 2);
    CHECK_THAT(refused.out, Catch::Matchers::Contains("not a checkpoint (no /checkpoint group)"));
  }
  SECTION("a checkpoint with a value out of range") {
    {
      dem::h5::Handle f = dem::h5::open_file_write(out + ".checkpoint");
      dem::h5::Handle g = dem::h5::open_group(f, "checkpoint/state");
      H5Adelete(g, "energy_started");
      dem::h5::set_attribute(g, "energy_started", std::int64_t{7});
    }
    const auto refused = dem_stderr(run + " --resume");
    CHECK(refused.exit_code == 2);
    CHECK_THAT(refused.out, Catch::Matchers::Contains("attribute energy_started = 7 is outside [0, 1]"));
  }
}

TEST_CASE("a finished run removes its checkpoint; --no-resume starts over", "[run][checkpoint]") {
  const std::string dir = dem::test::scratch_dir("checkpoint_done");
  dem::test::write_text(dir + "/s.yaml",
                        dem::test::tiny_scene("  - {name: squeeze, type: strain_rate, strain_rate: [2, 2, 2], duration: 6.0e-4}\n",
                                              "{kn: 1.0e6, ks: 1.0e6, friction: 0.5}",
                                              "output: {interval: 50, checkpoint_interval: 100}\n"));
  const std::string out = dir + "/r.h5";
  dem::test::write_text(out + ".checkpoint", "left by someone else\n");
  const auto r = dem_stderr("run '" + dir + "/s.yaml' --out '" + out + "' --no-resume");
  CHECK(r.exit_code == 0);
  CHECK_THAT(r.out, !Catch::Matchers::Contains("resuming"));
  CHECK(fs::exists(out));
  CHECK_FALSE(fs::exists(out + ".checkpoint"));
  CHECK_FALSE(fs::exists(out + ".lock"));
}

TEST_CASE("dem run refuses an --out that is a folder, in a missing folder, or being written by another run",
          "[run][cli][input]") {
  const std::string dir = dem::test::scratch_dir("checkpoint_out");
  dem::test::write_text(dir + "/s.yaml", stopping_scene());
  fs::create_directories(dir + "/folder.h5");
  auto r = dem_stderr("run '" + dir + "/s.yaml' --out '" + dir + "/folder.h5'");
  CHECK(r.exit_code == 2);
  CHECK_THAT(r.out, Catch::Matchers::Contains("--out " + dir + "/folder.h5 is a directory, not a file name; nothing was run"));
  r = dem_stderr("run '" + dir + "/s.yaml' --out '" + dir + "/missing/r.h5'");
  CHECK(r.exit_code == 2);
  CHECK_THAT(r.out, Catch::Matchers::Contains("is in a folder that does not exist"));
  CHECK_FALSE(fs::exists(dir + "/missing"));

  // Another writer holds the lock: nothing of its result is touched.
  const std::string out = dir + "/r.h5";
  dem::test::write_text(out + ".partial", "another run's partial result\n");
  const int fd = open((out + ".lock").c_str(), O_RDWR | O_CREAT, 0644);
  REQUIRE(fd >= 0);
  REQUIRE(flock(fd, LOCK_EX | LOCK_NB) == 0);
  r = dem_stderr("run '" + dir + "/s.yaml' --out '" + out + "'");
  close(fd);
  CHECK(r.exit_code == 2);
  CHECK_THAT(r.out, Catch::Matchers::Contains("another dem run is writing this result"));
  CHECK(dem::test::read_bytes(out + ".partial") == "another run's partial result\n");
}

TEST_CASE("a control stage with a shearing cell and cyclic loading resumes from its checkpoint bit for bit",
          "[run][checkpoint][sheared]") {
  // 64 spheres of 4.0-4.5 mm at 4.5 mm squeezed 4 % in 2,000 steps, then a control stage: simple
  // shear xy at 20/s (the cell tilts), zz strain cycling, xx and yy at 100 kPa, until the shear
  // strain since the stage start reaches 0.004 (about step 2,200); then a stress stage that cannot
  // settle in 50 steps stops the run. The last checkpoint, at step 2,100, is inside the control
  // stage: the resumed run must carry the stage's start values (p0, the strains the stop criterion
  // is measured from), the cycle's strain range, the tilts and the servo, or its rows would differ.
  const std::string dir = dem::test::scratch_dir("checkpoint_resume_control");
  dem::test::write_text(dir + "/s.yaml",
                        "name: control\n"
                        "particles:\n"
                        "  lattice: {n: [4, 4, 4], spacing: 4.5e-3, seed: 3}\n"
                        "  grading: {diameters: [4.0e-3, 4.5e-3], percent_finer: [0, 100]}\n"
                        "material: {kn: 1.0e6, ks: 1.0e6, friction: 0.5}\n"
                        "numerics: {time_step: 1.0e-6}\n"
                        "output: {interval: 50, checkpoint_interval: 100}\n"
                        "stages:\n"
                        "  - {name: compress, type: strain_rate, strain_rate: [20, 20, 20], duration: 2.0e-3}\n"
                        "  - {name: shear, type: control, reset_strain: true, duration: 1.0e-3,\n"
                        "     control: {xx: {stress: 1.0e5}, yy: {stress: 1.0e5}, zz: {strain_rate: 0}, xy: {strain_rate: 20},\n"
                        "               xz: {stress: 0}, yz: {stress: 0}},\n"
                        "     cyclic: {component: zz, quantity: strain, amplitude: 1.0e-3, period: 1.5e-4},\n"
                        "     until: {component: xy, strain: 0.004}}\n"
                        "  - {name: hold, type: stress, target: [1.0e5, 1.0e5, 1.0e5], rate: 1.0e9, hold: {max_duration: 5.0e-5}}\n");
  const std::string first = stop_at_checkpoint(dir, 2100);
  const auto tilt = column(first, "cell_tilt_12"), amplitude = column(first, "double_amplitude_strain");
  REQUIRE(*std::min_element(tilt.begin(), tilt.end()) < 0);  // the cell tilted (G_xy > 0 lowers xy)
  REQUIRE(*std::max_element(amplitude.begin(), amplitude.end()) > 0);

  resume_bit_for_bit(dir, 2100);
}

TEST_CASE("a stress stage's hold with a creep criterion resumes from its checkpoint bit for bit", "[run][checkpoint]") {
  // tests/engine/run/hold_criteria_test.cpp's compression with hold.creep_rate: its creep windows
  // start at step 10,000 and the stage ends at step 117,000, after the checkpoint at step 100,000;
  // a stress stage that cannot settle in 50 steps then stops the run. The resumed run must carry
  // the open creep window (its start and volume) or its windows, and so its end, would move.
  const std::string dir = dem::test::scratch_dir("checkpoint_resume_creep");
  dem::test::write_text(dir + "/s.yaml",
                        "name: creep\n"
                        "particles:\n"
                        "  lattice: {n: [5, 5, 5], spacing: 5.0e-3, seed: 4}\n"
                        "  grading: {diameters: [3.0e-3, 3.7e-3, 4.5e-3], percent_finer: [0, 50, 100]}\n"
                        "material: {density: 2650, kn: 1.0e6, ks: 1.0e6, friction: 0.3}\n"
                        "numerics: {time_step: 1.0e-6}\n"
                        "output: {interval: 100, checkpoint_interval: 50000}\n"
                        "stages:\n"
                        "  - {name: compress, type: stress, target: [1.0e5, 1.0e5, 1.0e5], rate: 1.0e7, max_strain_rate: 5.0,\n"
                        "     hold: {stress_tolerance: 0.005, unbalanced_force_ratio: 1.0e-2, check_interval: 100, max_duration: 2.0,\n"
                        "            creep_rate: 0.05, creep_window: 1.0e-3}}\n"
                        "  - {name: hold, type: stress, target: [2.0e5, 2.0e5, 2.0e5], rate: 1.0e9, hold: {max_duration: 5.0e-5}}\n");
  const std::string first = stop_at_checkpoint(dir, 100000);
  const auto stage = column(first, "stage"), step = column(first, "step");
  const auto hold_start = std::find(stage.begin(), stage.end(), 1.0);
  REQUIRE(hold_start != stage.end());
  CHECK(step[static_cast<std::size_t>(hold_start - stage.begin())] == 117000);  // the creep stage ended after the checkpoint

  resume_bit_for_bit(dir, 100000);
}

namespace {

// Adds one unit in the last place to the first value of a dataset of doubles, in place.
void nudge_dataset(const std::string& file, const std::string& path) {
  dem::h5::Handle f = dem::h5::open_file_write(file);
  dem::h5::Handle ds(H5Dopen2(f, path.c_str(), H5P_DEFAULT));
  REQUIRE(ds.id() >= 0);
  dem::h5::Handle space(H5Dget_space(ds));
  std::vector<double> v(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)));
  REQUIRE(!v.empty());
  REQUIRE(H5Dread(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) >= 0);
  v[0] = std::nextafter(v[0], 1e300);
  REQUIRE(H5Dwrite(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) >= 0);
}

// The same for a double attribute.
void nudge_attribute(const std::string& file, const std::string& object, const std::string& name) {
  dem::h5::Handle f = dem::h5::open_file_write(file);
  dem::h5::Handle o(H5Oopen(f, object.c_str(), H5P_DEFAULT));
  REQUIRE(o.id() >= 0);
  const double v = dem::h5::get_double_attribute(o, name);
  H5Adelete(o, name.c_str());
  dem::h5::set_attribute(o, name, std::nextafter(v, 1e300));
}

}  // namespace

TEST_CASE("a checkpoint with any one value changed is not resumed: it carries a checksum", "[run][checkpoint][input][checksum]") {
  // a checkpoint with one value changed, still readable and in range, resumed silently
  // into a "complete" result with another /state. The class swept: one value, changed by one unit
  // in its last place, in each part of a checkpoint (the state, the Verlet list, the energy
  // balance, the stage cursor, an attribute of /checkpoint, the time series and the particle
  // frames copied from the partial result, a root attribute). Each: --resume refuses (exit 2,
  // naming the checksum); by default the run warns and starts over from step 0 (and here ends as
  // the stopping scene does, exit 1).
  const std::string dir = dem::test::scratch_dir("checkpoint_checksum");
  dem::test::write_text(dir + "/s.yaml", stopping_scene());
  const std::string out = dir + "/r.h5", run = "run '" + dir + "/s.yaml' --out '" + out + "'";
  REQUIRE(dem_stderr(run).exit_code == 1);
  const std::string good = dir + "/good.checkpoint";
  fs::copy_file(out + ".checkpoint", good);
  {  // the untouched checkpoint resumes
    const auto r = dem_stderr(run + " --resume");
    CHECK(r.exit_code == 1);
    CHECK_THAT(r.out, Catch::Matchers::Contains("resuming from"));
  }
  struct Change {
    std::string what;
    std::function<void(const std::string&)> apply;
  };
  const std::vector<Change> changes = {
      {"a particle position of the state", [](const std::string& f) { nudge_dataset(f, "checkpoint/state/position"); }},
      {"a velocity of the state", [](const std::string& f) { nudge_dataset(f, "checkpoint/state/velocity"); }},
      {"the Verlet list's positions at its build", [](const std::string& f) { nudge_dataset(f, "checkpoint/state/verlet_position_fractional_at_build"); }},
      {"the stage cursor", [](const std::string& f) { nudge_dataset(f, "checkpoint/cursor/strain_at_start"); }},
      {"an attribute of /checkpoint", [](const std::string& f) { nudge_attribute(f, "checkpoint", "time"); }},
      {"a time-series value", [](const std::string& f) { nudge_dataset(f, "timeseries/p"); }},
      {"a particle frame", [](const std::string& f) { nudge_dataset(f, "particles/all/position/value"); }},
      {"an energy attribute of the state", [](const std::string& f) { nudge_attribute(f, "checkpoint/state", "energy_work_by_cell"); }},
  };
  for (const Change& c : changes) {
    INFO(c.what);
    fs::copy_file(good, out + ".checkpoint", fs::copy_options::overwrite_existing);
    c.apply(out + ".checkpoint");
    const auto refused = dem_stderr(run + " --resume");
    INFO(refused.out);
    CHECK(refused.exit_code == 2);
    CHECK_THAT(refused.out, Catch::Matchers::Contains("cannot resume: " + out + ".checkpoint: checksum ") &&
                                Catch::Matchers::Contains("the checkpoint was changed after it was written"));
    const auto fresh = dem_stderr(run);
    CHECK(fresh.exit_code == 1);
    CHECK_THAT(fresh.out, Catch::Matchers::Contains("warning: not resuming: " + out + ".checkpoint: checksum "));
    CHECK_THAT(fresh.out, !Catch::Matchers::Contains("resuming from"));
  }
}
