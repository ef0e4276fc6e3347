#include "analysis/time_series.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>

#include "analysis/fabric.hpp"
#include "analysis/measurements.hpp"

namespace dem {

const std::vector<SeriesColumn>& series_columns() {
  static const std::vector<SeriesColumn> columns = {
      {"step", "1", "time step index"},
      {"time", "s", "simulated time"},
      {"stage", "1", "stage index (0-based, order of the scene)"},
      {"cycle", "1", "stress-path cycle, or cycle of a control stage's cyclic loading (0 outside cycles)"},
      {"leg", "1", "stress-path leg index from 0 (-1 outside paths)"},
      {"leg_end", "1", "1 if the row is taken at the end of a leg"},
      {"cycle_end", "1", "1 if the row is taken at the end of a cycle"},
      {"stress_11", "Pa", "contact stress, compression positive"},
      {"stress_22", "Pa", ""},
      {"stress_33", "Pa", ""},
      {"stress_12", "Pa", ""},
      {"stress_13", "Pa", ""},
      {"stress_23", "Pa", ""},
      {"p", "Pa", "mean stress (s1+s2+s3)/3"},
      {"q", "Pa", "deviator stress sqrt(((s1-s2)^2+(s2-s3)^2+(s1-s3)^2)/2), principal values"},
      {"q_over_p", "1", "q / p"},
      {"sigma1_over_sigma3", "1", "stress_11 / stress_33 (the paper's axes)"},
      {"sigma_max_over_min", "1", "largest / smallest principal stress"},
      {"pi_stress_x", "1", "pi-plane x of the stress, (s33 - s22)/(sqrt(2) p)"},
      {"pi_stress_y", "1", "pi-plane y of the stress, (2 s11 - s22 - s33)/(sqrt(6) p)"},
      {"cell_length_1", "m", ""},
      {"cell_length_2", "m", ""},
      {"cell_length_3", "m", ""},
      {"strain_1", "1", "true strain -ln(L/L0), compression positive"},
      {"strain_2", "1", ""},
      {"strain_3", "1", ""},
      {"volumetric_strain", "1", "1 - V/V0"},
      {"deviatoric_strain", "1", "paper Eq. 4: sqrt(2/3 ((e1-e2)^2+(e2-e3)^2+(e1-e3)^2)), sqrt(3) x the usual one"},
      {"deviatoric_strain_equivalent", "1", "usual equivalent strain sqrt(2/9 ((e1-e2)^2+(e2-e3)^2+(e1-e3)^2))"},
      {"pi_strain_increment_x", "1", "pi-plane x of the strain increment since the previous leg end"},
      {"pi_strain_increment_y", "1", "pi-plane y of the strain increment since the previous leg end"},
      {"void_ratio", "1", "(V - Vs)/Vs, overlaps not subtracted"},
      {"coordination_number", "1", "2 Nc / Np, rattlers included"},
      {"coordination_number_mechanical", "1", "(2 Nc - N1)/(Np - N0 - N1) (Thornton 2000)"},
      {"sliding_fraction", "1", "Ns / Nc"},
      {"contacts", "1", "Nc"},
      {"mean_normal_force", "N", "mean f_n over contacts"},
      {"fabric_11", "1", "F = (1/Nc) sum n n over all contacts (paper Eq. 8)"},
      {"fabric_22", "1", ""},
      {"fabric_33", "1", ""},
      {"fabric_12", "1", ""},
      {"fabric_13", "1", ""},
      {"fabric_23", "1", ""},
      {"strong_fabric_11", "1", "F^s = (1/Nc) sum over f_n > mean f_n of n n, total Nc (paper Eqs. 9-10)"},
      {"strong_fabric_22", "1", ""},
      {"strong_fabric_33", "1", ""},
      {"strong_fabric_12", "1", ""},
      {"strong_fabric_13", "1", ""},
      {"strong_fabric_23", "1", ""},
      {"fabric_ratio", "1", "F_d / F_m"},
      {"strong_fabric_ratio", "1", "F^s_d / F^s_m"},
      {"unbalanced_force_ratio", "1", "mean |net force| / mean normal contact force"},
      {"kinetic_energy_translational", "J", "of the fluctuating velocities"},
      {"kinetic_energy_rotational", "J", ""},
      {"inertial_number", "1", "max|strain rate| d_mean sqrt(rho/p), over the axial and shear rates"},
      {"strain_rate_1", "1/s", "applied in the last step, compression positive"},
      {"strain_rate_2", "1/s", ""},
      {"strain_rate_3", "1/s", ""},
      {"neighbour_list_builds", "1", "Verlet list rebuilds so far"},
      // The energy balance (dynamics/simulation.hpp, EnergyBalance): at the last force evaluation,
      // one step before `step`; cumulative values count from the run's first step.
      {"elastic_energy_normal", "J", "stored in the normal springs (linear: sum 1/2 kn overlap^2)"},
      {"elastic_energy_tangential", "J", "stored in the tangential springs (linear: sum 1/2 ks |u_s|^2)"},
      {"kinetic_energy_centred", "J", "translational + rotational, 1/2 m v(n-1/2).v(n+1/2): the kinetic energy of the balance"},
      {"work_by_cell", "J", "integral of V sigma:d(eps) since the run started, compression positive"},
      {"dissipated_by_damping", "J", "since the run started"},
      {"dissipated_by_friction", "J", "by sliding contacts since the run started"},
      {"energy_closure_error", "1", "|E_in - (E_stored + E_dissipated)| / E_in, E_in = stored energy at the start + work by the cell"},
      {"elastic_energy_rolling", "J", "stored in the rolling springs, sum 1/2 kr |u_r|^2 (0 without rolling resistance)"},
      {"dissipated_by_rolling", "J", "by rolling resistance at its cap since the run started"},
      {"shear_strain_12", "1", "engineering shear strain since the reference, compression positive (cell/periodic_cell.hpp)"},
      {"shear_strain_13", "1", ""},
      {"shear_strain_23", "1", ""},
      {"shear_rate_12", "1/s", "engineering shear strain rate applied in the last step, compression positive"},
      {"shear_rate_13", "1/s", ""},
      {"shear_rate_23", "1/s", ""},
      {"cell_tilt_12", "m", "tilt xy of the cell (the x offset of its second vector), within +-L1/2 after re-mapping"},
      {"cell_tilt_13", "m", "tilt xz"},
      {"cell_tilt_23", "m", "tilt yz"},
      {"pore_pressure_ratio", "1", "control stages: r_u = 1 - p/p0, p0 at the stage start (constant volume: the excess pore pressure ratio); 0 elsewhere"},
      {"double_amplitude_strain", "1", "control stages with cyclic loading: max - min strain of the cyclic component in the current cycle"},
  };
  return columns;
}

std::vector<double> measure_row(const Simulation& sim, const RowContext& where) {
  const ContactCounts c = count_contacts(sim, true);
  const Mat3 fabric = fabric_tensor(c.normals);
  const Mat3 strong = strong_fabric_tensor(c.normals, c.normal_forces_N);
  const auto ratio = [](const Mat3& t) { return mean_invariant(t) > 0 ? deviator_invariant(t) / mean_invariant(t) : 0.0; };
  const Mat3& s = c.stress_Pa;
  const PeriodicCell& cell = sim.cell();
  const Vec3 eps = cell.strain();
  const Vec3& L = cell.lengths();
  const Vec3& r = sim.strain_rate();
  const std::size_t n = sim.particles().size();
  const EnergyBalance& e = sim.energy();
  const double volumetric = 1.0 - cell.volume() / cell.reference_lengths().prod();
  const double p = mean_stress(s), q = deviator_stress(s);
  const Eigen::Vector2d pi_s = p > 0 ? Eigen::Vector2d(pi_plane(s.diagonal()) / p) : Eigen::Vector2d::Zero();
  const Eigen::Vector2d pi_de = pi_plane(eps - where.strain_at_previous_leg_end);
  const Vec3 principal = Eigen::SelfAdjointEigenSolver<Mat3>(s, Eigen::EigenvaluesOnly).eigenvalues();
  const double e_sum = (eps[0] - eps[1]) * (eps[0] - eps[1]) + (eps[1] - eps[2]) * (eps[1] - eps[2]) +
                       (eps[0] - eps[2]) * (eps[0] - eps[2]);
  return {static_cast<double>(sim.step_count()),
          sim.time(),
          static_cast<double>(where.stage),
          static_cast<double>(where.cycle),
          static_cast<double>(where.leg),
          where.leg_end ? 1.0 : 0.0,
          where.cycle_end ? 1.0 : 0.0,
          s(0, 0), s(1, 1), s(2, 2), s(0, 1), s(0, 2), s(1, 2),
          p,
          q,
          p > 0 ? q / p : 0.0,
          s(2, 2) > 0 ? s(0, 0) / s(2, 2) : 0.0,
          principal[0] > 0 ? principal[2] / principal[0] : 0.0,
          pi_s[0], pi_s[1],
          L[0], L[1], L[2],
          eps[0], eps[1], eps[2],
          volumetric,
          std::sqrt(2.0 / 3.0 * e_sum),
          std::sqrt(2.0 / 9.0 * e_sum),
          pi_de[0], pi_de[1],
          void_ratio(sim.particles(), cell),
          coordination_number(c.contacts, n),
          mechanical_coordination_number(c, n),
          c.contacts ? static_cast<double>(c.sliding) / static_cast<double>(c.contacts) : 0.0,
          static_cast<double>(c.contacts),
          c.mean_normal_force_N,
          fabric(0, 0), fabric(1, 1), fabric(2, 2), fabric(0, 1), fabric(0, 2), fabric(1, 2),
          strong(0, 0), strong(1, 1), strong(2, 2), strong(0, 1), strong(0, 2), strong(1, 2),
          ratio(fabric),
          ratio(strong),
          unbalanced_force_ratio(sim),
          translational_kinetic_energy(sim.particles()),
          rotational_kinetic_energy(sim.particles()),
          inertial_number(sim, p),
          r[0], r[1], r[2],
          static_cast<double>(sim.verlet_list().builds()),
          // Before a run's first step nothing has evaluated the forces: the energies of that row
          // are the state's own (the springs at these positions, the particles' motion).
          e.started ? sim.sums().elastic_normal_J : c.elastic_normal_J,
          e.started ? sim.sums().elastic_tangential_J : c.elastic_tangential_J,
          e.started ? e.kinetic : translational_kinetic_energy(sim.particles()) + rotational_kinetic_energy(sim.particles()),
          e.work_by_cell,
          e.dissipated_damping,
          e.dissipated_friction,
          e.closure_error(),
          e.started ? sim.sums().elastic_rolling_J : c.elastic_rolling_J,
          e.dissipated_rolling,
          cell.shear_strain()[0], cell.shear_strain()[1], cell.shear_strain()[2],
          sim.rates().shear[0], sim.rates().shear[1], sim.rates().shear[2],
          cell.tilts()[0], cell.tilts()[1], cell.tilts()[2],
          where.mean_stress_at_stage_start > 0 ? 1 - p / where.mean_stress_at_stage_start : 0.0,
          where.double_amplitude_strain};
}

}  // namespace dem
