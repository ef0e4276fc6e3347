// The first row of a run's time series carries the sample's true state at t = 0, energies too
//: before the first step nothing has evaluated the forces, and the row used to report
// 0 J of elastic energy for a sample full of loaded contacts.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "analysis/measurements.hpp"
#include "analysis/time_series.hpp"
#include "engine/test_support.hpp"

using namespace dem;

namespace {

double column(const std::vector<double>& row, const std::string& name) {
  const auto& cols = series_columns();
  for (std::size_t c = 0; c < cols.size(); ++c)
    if (cols[c].name == name) return row[c];
  FAIL("no column " << name);
  return 0.0;
}

}  // namespace

TEST_CASE("measure_row before the first step: elastic energy of the loaded contacts, 1/2 kn overlap^2 each", "[analysis][energy]") {
  // Equal spheres of d = 2 mm on a 4 x 4 x 4 simple cubic lattice, spacing 1.99 mm along axis 1
  // and 2.1 mm across: 64 contacts, all along axis 1 with overlap 10 um, unloaded tangential
  // springs, particles at rest. Linear law: each holds 1/2 kn (10 um)^2.
  const double d = 2e-3, kn = 1e6, overlap = 10e-6;
  const PeriodicCell cell(4 * Vec3(d - overlap, 2.1e-3, 2.1e-3));
  Particles p;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 4; ++k) p.add(Vec3((i + 0.5) / 4, (j + 0.5) / 4, (k + 0.5) / 4), d / 2, 2650);
  const Simulation sim(p, cell, test::material(kn), test::no_damping(), 1e-7, 0.05 * d);
  REQUIRE_FALSE(sim.energy().started);
  const auto row = measure_row(sim, {});
  CHECK(column(row, "contacts") == 64);
  // The sum of 64 equal terms, each with the rounding of one overlap (d - spacing): relative 1e-9.
  CHECK(column(row, "elastic_energy_normal") == Approx(64 * 0.5 * kn * overlap * overlap).epsilon(1e-9));
  CHECK(column(row, "elastic_energy_tangential") == 0);
  CHECK(column(row, "kinetic_energy_centred") == 0);
  CHECK(column(row, "work_by_cell") == 0);
  CHECK(column(row, "energy_closure_error") == 0);
}
