// The quantity registry (validation/judge/quantities.hpp) on hand-made drained shears: the peak and
// critical-state friction angles and the critical-state void ratio, the mean over tests or the one
// test a row names, what each quantity reads, and a shear too short for the critical state.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "analysis/time_series.hpp"
#include "judge/quantities.hpp"

using validation::Reads;

namespace {

constexpr double deg = std::numbers::pi / 180;

// A drained triaxial compression along z at p = 100 kPa, rows every 0.2 % of axial strain up to
// `last` (0.4: 40 %): the mobilised friction angle is `phi_cs` except a plateau of `phi_peak` for
// 4 ... 6 % of axial strain, and the void ratio 0.7 before 30 % and `e_cs` from there on. The
// stresses come from the angle through s1/s3 = (1 + sin phi)/(1 - sin phi), the inverse of the
// definition sin phi = (s1 - s3)/(s1 + s3) that the quantities use.
validation::TestResult shear(const std::string& name, double phi_peak, double phi_cs, double e_cs, double last = 0.4) {
  validation::TestResult t;
  t.name = name;
  for (const dem::SeriesColumn& col : dem::series_columns()) t.series[col.name] = {};
  for (int i = 0; 0.002 * i <= last + 1e-12; ++i) {
    const double strain = 0.002 * i, phi = (i >= 20 && i <= 30) ? phi_peak : phi_cs;
    const double s = std::sin(phi * deg), ratio = (1 + s) / (1 - s), lateral = 3e5 / (ratio + 2);
    for (auto& [column, v] : t.series) v.push_back(0.0);
    t.series["strain_3"].back() = strain;
    t.series["stress_11"].back() = lateral, t.series["stress_22"].back() = lateral, t.series["stress_33"].back() = ratio * lateral;
    t.series["void_ratio"].back() = strain >= 0.3 - 1e-12 ? e_cs : 0.7;
    t.series["coordination_number"].back() = 4, t.series["coordination_number_mechanical"].back() = 4.5;
  }
  return t;
}

validation::Measured compute(const std::string& quantity, const validation::DensityResults& r, const std::string& test = "") {
  validation::QuantityRequest q;
  q.quantity = quantity, q.test = test;
  return validation::compute(q, r);
}

}  // namespace

TEST_CASE("peak and critical-state friction angles and void ratio of drained shears", "[quantities][critical-state]") {
  validation::DensityResults r;
  r.tests = {shear("compression", 40, 30, 0.60), shear("compression_mu1", 36, 26, 0.64)};
  SECTION("the test a row names") {
    // The smoothing window of the peak (1 % of axial strain) fits in the plateau: the peak is the plateau's.
    CHECK(compute("peak_friction_angle", r, "compression").value == Approx(40).epsilon(1e-12));
    CHECK(compute("critical_state_friction_angle", r, "compression").value == Approx(30).epsilon(1e-12));
    CHECK(compute("critical_state_void_ratio", r, "compression").value == Approx(0.60).epsilon(1e-12));
    CHECK(compute("peak_friction_angle", r, "compression_mu1").value == Approx(36).epsilon(1e-12));
    CHECK(compute("peak_friction_angle", r, "compression").note == "mean of tests compression");
  }
  SECTION("no test named: the mean over the tests") {
    CHECK(compute("peak_friction_angle", r).value == Approx(38).epsilon(1e-12));
    CHECK(compute("critical_state_friction_angle", r).value == Approx(28).epsilon(1e-12));
    CHECK(compute("critical_state_void_ratio", r).value == Approx(0.62).epsilon(1e-12));
    CHECK(compute("peak_friction_angle", r).note == "mean of tests compression,compression_mu1");
  }
  SECTION("a test the results lack, and a shear that stops before the critical state") {
    CHECK_FALSE(compute("peak_friction_angle", r, "extension").value);
    validation::DensityResults short_shear;
    short_shear.tests = {shear("compression", 40, 30, 0.60, 0.2)};
    CHECK(compute("peak_friction_angle", short_shear).value == Approx(40).epsilon(1e-12));
    const validation::Measured cs = compute("critical_state_void_ratio", short_shear);
    CHECK_FALSE(cs.value);
    CHECK(cs.note == "no test reaches 30 % axial strain");
  }
  SECTION("<quantity>_magnitude is the absolute value") {
    validation::DensityResults negative;
    negative.tests = {shear("compression", 40, 30, -0.5)};  // not a void ratio: a sign to drop
    CHECK(compute("critical_state_void_ratio_magnitude", negative).value == Approx(0.5).epsilon(1e-12));
  }
}

TEST_CASE("the coordination of a prepared sample with and without its rattlers", "[quantities]") {
  validation::DensityResults r;
  SECTION("no prepared sample: no value") {
    CHECK_FALSE(compute("coordination_without_rattlers_after_preparation", r).value);
  }
  SECTION("the mechanical coordination is read, not the one with rattlers") {
    // 10 spheres, 2 of them with no contact and 1 with one contact, 25 contacts: 2 Nc / Np = 5 and
    // (2 Nc - N1) / (Np - N0 - N1) = 49 / 7 = 7, as the engine's columns hold them.
    r.prepared = true;
    r.sample = {{"coordination_number", 5.0}, {"coordination_number_mechanical", 49.0 / 7.0}};
    CHECK(compute("coordination_without_rattlers_after_preparation", r).value == Approx(7).epsilon(1e-12));
    CHECK(compute("coordination_after_preparation", r).value == Approx(5).epsilon(1e-12));
  }
}

TEST_CASE("what each quantity reads decides which runs a row needs", "[quantities]") {
  CHECK(validation::reads_of("coordination_without_rattlers_after_preparation") == Reads::Preparation);
  CHECK(validation::reads_of("void_ratio_after_preparation") == Reads::Preparation);
  CHECK(validation::reads_of("cell_side_cm_after_preparation") == Reads::Preparation);
  CHECK(validation::reads_of("ev_growth") == Reads::Tests);
  CHECK(validation::reads_of("ev_growth_magnitude") == Reads::Tests);
  CHECK(validation::reads_of("peak_friction_angle") == Reads::Tests);
  CHECK(validation::reads_of("ev_lead") == Reads::TestAmongTests);
  CHECK(validation::known_quantity("critical_state_void_ratio_magnitude"));
  CHECK_FALSE(validation::known_quantity("phi_peak"));
  CHECK_THROWS_AS(validation::reads_of("phi_peak"), std::out_of_range);
  const std::vector<std::string> known = validation::known_quantities();
  CHECK(std::find(known.begin(), known.end(), "critical_state_friction_angle") != known.end());
}

TEST_CASE("a quantity meant for a monotonic shear warns when it reads a cyclic test", "[quantities][warnings]") {
  validation::DensityResults r;
  r.tests = {shear("compression", 40, 30, 0.60)};
  // A drained shear counts no cycle: no misfit.
  CHECK(compute("peak_friction_angle", r).misfit.empty());
  // The same rows marked as 3 cycles of a cyclic path (the time series' cycle column): the value is
  // computed all the same, and the misfit names the test and its cycles.
  validation::TestResult cyclic = shear("test1", 40, 30, 0.60);
  std::vector<double>& cycle = cyclic.series["cycle"];
  for (std::size_t i = 0; i < cycle.size(); ++i) cycle[i] = static_cast<double>(3 * i / cycle.size() + 1);
  r.tests.push_back(cyclic);
  const validation::Measured both = compute("peak_friction_angle", r);
  CHECK(both.value == Approx(40).epsilon(1e-12));
  CHECK(both.misfit == "peak_friction_angle is meant for a monotonic shear; it read cyclic tests: test1 (3 cycles)");
  CHECK(compute("critical_state_void_ratio", r, "test1").misfit.find("test1 (3 cycles)") != std::string::npos);
  CHECK(compute("peak_friction_angle", r, "compression").misfit.empty());  // the row reads the drained test only
  // A quantity of cyclic tests has no such warning.
  CHECK(compute("ev_growth", r).misfit.empty());
}
