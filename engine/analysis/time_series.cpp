#include "analysis/time_series.hpp"

#include "analysis/measurements.hpp"

namespace dem {

const std::vector<SeriesColumn>& series_columns() {
  static const std::vector<SeriesColumn> columns = {
      {"step", "1", "time step index"},
      {"time", "s", "simulated time"},
      {"stage", "1", "stage index (0-based, order of the scene)"},
      {"stress_11", "Pa", "contact stress, compression positive"},
      {"stress_22", "Pa", ""},
      {"stress_33", "Pa", ""},
      {"stress_12", "Pa", ""},
      {"stress_13", "Pa", ""},
      {"stress_23", "Pa", ""},
      {"p", "Pa", "mean stress (s1+s2+s3)/3"},
      {"q", "Pa", "deviator stress sqrt(((s1-s2)^2+(s2-s3)^2+(s1-s3)^2)/2), principal values"},
      {"cell_length_1", "m", ""},
      {"cell_length_2", "m", ""},
      {"cell_length_3", "m", ""},
      {"strain_1", "1", "true strain -ln(L/L0), compression positive"},
      {"strain_2", "1", ""},
      {"strain_3", "1", ""},
      {"volumetric_strain", "1", "1 - V/V0"},
      {"void_ratio", "1", "(V - Vs)/Vs, overlaps not subtracted"},
      {"coordination_number", "1", "2 Nc / Np, rattlers included"},
      {"coordination_number_mechanical", "1", "(2 Nc - N1)/(Np - N0 - N1) (Thornton 2000)"},
      {"sliding_fraction", "1", "Ns / Nc"},
      {"contacts", "1", "Nc"},
      {"mean_normal_force", "N", "mean f_n over contacts"},
      {"unbalanced_force_ratio", "1", "mean |net force| / mean normal contact force"},
      {"kinetic_energy_translational", "J", "of the fluctuating velocities"},
      {"kinetic_energy_rotational", "J", ""},
      {"inertial_number", "1", "max|strain rate| d_mean sqrt(rho/p)"},
      {"strain_rate_1", "1/s", "applied in the last step, compression positive"},
      {"strain_rate_2", "1/s", ""},
      {"strain_rate_3", "1/s", ""},
      {"neighbour_list_builds", "1", "Verlet list rebuilds so far"},
  };
  return columns;
}

std::vector<double> measure_row(const Simulation& sim, int stage_index) {
  const ContactCounts c = count_contacts(sim);
  const Mat3& s = c.stress_Pa;
  const PeriodicCell& cell = sim.cell();
  const Vec3 eps = cell.strain();
  const Vec3& L = cell.lengths();
  const Vec3& r = sim.strain_rate();
  const std::size_t n = sim.particles().size();
  const double volumetric = 1.0 - cell.volume() / cell.reference_lengths().prod();
  return {static_cast<double>(sim.step_count()),
          sim.time(),
          static_cast<double>(stage_index),
          s(0, 0), s(1, 1), s(2, 2), s(0, 1), s(0, 2), s(1, 2),
          mean_stress(s),
          deviator_stress(s),
          L[0], L[1], L[2],
          eps[0], eps[1], eps[2],
          volumetric,
          void_ratio(sim.particles(), cell),
          coordination_number(c.contacts, n),
          mechanical_coordination_number(c, n),
          c.contacts ? static_cast<double>(c.sliding) / static_cast<double>(c.contacts) : 0.0,
          static_cast<double>(c.contacts),
          c.mean_normal_force_N,
          unbalanced_force_ratio(sim),
          sim.kinetic_energy(),
          rotational_kinetic_energy(sim.particles()),
          inertial_number(sim),
          r[0], r[1], r[2],
          static_cast<double>(sim.verlet_list().builds())};
}

}  // namespace dem
