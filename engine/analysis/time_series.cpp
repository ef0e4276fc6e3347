#include "analysis/time_series.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>

#include "analysis/fabric.hpp"
#include "analysis/measurements.hpp"

namespace dem {

namespace {

// What the columns of one row are computed from: the state, where the row is taken, and what
// several columns share (the contact survey, fabric, stress invariants), computed once per row.
struct RowInputs {
  RowInputs(const Simulation& simulation, const RowContext& row_context)
      : sim(simulation), where(row_context), cell(sim.cell()), e(sim.energy()), c(count_contacts(sim, true)),
        s(c.stress_Pa), fabric(fabric_tensor(c.normals)), strong(strong_fabric_tensor(c.normals, c.normal_forces_N)),
        eps(cell.strain()), p(mean_stress(s)), q(deviator_stress(s)) {
    pi_s = p > 0 ? Eigen::Vector2d(pi_plane(s.diagonal()) / p) : Eigen::Vector2d::Zero();
    pi_de = pi_plane(eps - where.strain_at_previous_leg_end);
    principal = Eigen::SelfAdjointEigenSolver<Mat3>(s, Eigen::EigenvaluesOnly).eigenvalues();
    e_sum = (eps[0] - eps[1]) * (eps[0] - eps[1]) + (eps[1] - eps[2]) * (eps[1] - eps[2]) +
            (eps[0] - eps[2]) * (eps[0] - eps[2]);
  }
  RowInputs(const RowInputs&) = delete;  // `s` refers into `c`
  const Simulation& sim;
  const RowContext& where;
  const PeriodicCell& cell;
  const EnergyBalance e;  // a copy: Simulation::energy() returns one
  const ContactCounts c;
  const Mat3& s;  // the contact stress
  const Mat3 fabric, strong;
  const Vec3 eps;  // true strain
  const double p, q;
  Eigen::Vector2d pi_s, pi_de;  // pi-plane stress / p, strain increment since the previous leg end
  Vec3 principal;               // principal stresses, ascending
  double e_sum = 0;             // sum of the squared differences of the principal strains
};

using In = const RowInputs&;

double anisotropy(const Mat3& t) { return mean_invariant(t) > 0 ? deviator_invariant(t) / mean_invariant(t) : 0.0; }

// The columns of /timeseries, in the file's order. A new column is one entry here (and a test of
// its value in tests/engine/analysis/).
const ColumnDef<RowInputs> columns[] = {
    {"step", "1", "time step index", [](In r) { return static_cast<double>(r.sim.step_count()); }},
    {"time", "s", "simulated time", [](In r) { return r.sim.time(); }},
    {"stage", "1", "stage index (0-based, order of the scene)", [](In r) { return static_cast<double>(r.where.stage); }},
    {"cycle", "1", "stress-path cycle, or cycle of a control stage's cyclic loading (0 outside cycles)",
     [](In r) { return static_cast<double>(r.where.cycle); }},
    {"leg", "1", "stress-path leg index from 0 (-1 outside paths)", [](In r) { return static_cast<double>(r.where.leg); }},
    {"leg_end", "1", "1 if the row is taken at the end of a leg", [](In r) { return r.where.leg_end ? 1.0 : 0.0; }},
    {"cycle_end", "1", "1 if the row is taken at the end of a cycle", [](In r) { return r.where.cycle_end ? 1.0 : 0.0; }},
    {"stress_11", "Pa", "contact stress, compression positive", [](In r) { return r.s(0, 0); }},
    {"stress_22", "Pa", "", [](In r) { return r.s(1, 1); }},
    {"stress_33", "Pa", "", [](In r) { return r.s(2, 2); }},
    {"stress_12", "Pa", "", [](In r) { return r.s(0, 1); }},
    {"stress_13", "Pa", "", [](In r) { return r.s(0, 2); }},
    {"stress_23", "Pa", "", [](In r) { return r.s(1, 2); }},
    {"p", "Pa", "mean stress (s1+s2+s3)/3", [](In r) { return r.p; }},
    {"q", "Pa", "deviator stress sqrt(((s1-s2)^2+(s2-s3)^2+(s1-s3)^2)/2), principal values", [](In r) { return r.q; }},
    {"q_over_p", "1", "q / p", [](In r) { return r.p > 0 ? r.q / r.p : 0.0; }},
    {"sigma1_over_sigma3", "1", "stress_11 / stress_33 (the paper's axes)",
     [](In r) { return r.s(2, 2) > 0 ? r.s(0, 0) / r.s(2, 2) : 0.0; }},
    {"sigma_max_over_min", "1", "largest / smallest principal stress",
     [](In r) { return r.principal[0] > 0 ? r.principal[2] / r.principal[0] : 0.0; }},
    {"pi_stress_x", "1", "pi-plane x of the stress, (s33 - s22)/(sqrt(2) p)", [](In r) { return r.pi_s[0]; }},
    {"pi_stress_y", "1", "pi-plane y of the stress, (2 s11 - s22 - s33)/(sqrt(6) p)", [](In r) { return r.pi_s[1]; }},
    {"cell_length_1", "m", "", [](In r) { return r.cell.lengths()[0]; }},
    {"cell_length_2", "m", "", [](In r) { return r.cell.lengths()[1]; }},
    {"cell_length_3", "m", "", [](In r) { return r.cell.lengths()[2]; }},
    {"strain_1", "1", "true strain -ln(L/L0), compression positive", [](In r) { return r.eps[0]; }},
    {"strain_2", "1", "", [](In r) { return r.eps[1]; }},
    {"strain_3", "1", "", [](In r) { return r.eps[2]; }},
    {"volumetric_strain", "1", "1 - V/V0",
     [](In r) { return 1.0 - r.cell.volume() / r.cell.reference_lengths().prod(); }},
    {"deviatoric_strain", "1", "paper Eq. 4: sqrt(2/3 ((e1-e2)^2+(e2-e3)^2+(e1-e3)^2)), sqrt(3) x the usual one",
     [](In r) { return std::sqrt(2.0 / 3.0 * r.e_sum); }},
    {"deviatoric_strain_equivalent", "1", "usual equivalent strain sqrt(2/9 ((e1-e2)^2+(e2-e3)^2+(e1-e3)^2))",
     [](In r) { return std::sqrt(2.0 / 9.0 * r.e_sum); }},
    {"pi_strain_increment_x", "1", "pi-plane x of the strain increment since the previous leg end", [](In r) { return r.pi_de[0]; }},
    {"pi_strain_increment_y", "1", "pi-plane y of the strain increment since the previous leg end", [](In r) { return r.pi_de[1]; }},
    {"void_ratio", "1", "(V - Vs)/Vs, overlaps not subtracted", [](In r) { return void_ratio(r.sim.particles(), r.cell); }},
    {"coordination_number", "1", "2 Nc / Np, rattlers included",
     [](In r) { return coordination_number(r.c.contacts, r.sim.particles().size()); }},
    {"coordination_number_mechanical", "1", "(2 Nc - N1)/(Np - N0 - N1) (Thornton 2000)",
     [](In r) { return mechanical_coordination_number(r.c, r.sim.particles().size()); }},
    {"sliding_fraction", "1", "Ns / Nc",
     [](In r) { return r.c.contacts ? static_cast<double>(r.c.sliding) / static_cast<double>(r.c.contacts) : 0.0; }},
    {"contacts", "1", "Nc", [](In r) { return static_cast<double>(r.c.contacts); }},
    {"mean_normal_force", "N", "mean f_n over contacts", [](In r) { return r.c.mean_normal_force_N; }},
    {"fabric_11", "1", "F = (1/Nc) sum n n over all contacts (paper Eq. 8)", [](In r) { return r.fabric(0, 0); }},
    {"fabric_22", "1", "", [](In r) { return r.fabric(1, 1); }},
    {"fabric_33", "1", "", [](In r) { return r.fabric(2, 2); }},
    {"fabric_12", "1", "", [](In r) { return r.fabric(0, 1); }},
    {"fabric_13", "1", "", [](In r) { return r.fabric(0, 2); }},
    {"fabric_23", "1", "", [](In r) { return r.fabric(1, 2); }},
    {"strong_fabric_11", "1", "F^s = (1/Nc) sum over f_n > mean f_n of n n, total Nc (paper Eqs. 9-10)",
     [](In r) { return r.strong(0, 0); }},
    {"strong_fabric_22", "1", "", [](In r) { return r.strong(1, 1); }},
    {"strong_fabric_33", "1", "", [](In r) { return r.strong(2, 2); }},
    {"strong_fabric_12", "1", "", [](In r) { return r.strong(0, 1); }},
    {"strong_fabric_13", "1", "", [](In r) { return r.strong(0, 2); }},
    {"strong_fabric_23", "1", "", [](In r) { return r.strong(1, 2); }},
    {"fabric_ratio", "1", "F_d / F_m", [](In r) { return anisotropy(r.fabric); }},
    {"strong_fabric_ratio", "1", "F^s_d / F^s_m", [](In r) { return anisotropy(r.strong); }},
    {"unbalanced_force_ratio", "1", "mean |net force| / mean normal contact force", [](In r) { return unbalanced_force_ratio(r.sim); }},
    {"kinetic_energy_translational", "J", "of the fluctuating velocities",
     [](In r) { return translational_kinetic_energy(r.sim.particles()); }},
    {"kinetic_energy_rotational", "J", "", [](In r) { return rotational_kinetic_energy(r.sim.particles()); }},
    {"inertial_number", "1", "max|strain rate| d_mean sqrt(rho/p), over the axial and shear rates",
     [](In r) { return inertial_number(r.sim, r.p); }},
    {"strain_rate_1", "1/s", "applied in the last step, compression positive", [](In r) { return r.sim.strain_rate()[0]; }},
    {"strain_rate_2", "1/s", "", [](In r) { return r.sim.strain_rate()[1]; }},
    {"strain_rate_3", "1/s", "", [](In r) { return r.sim.strain_rate()[2]; }},
    {"neighbour_list_builds", "1", "Verlet list rebuilds so far", [](In r) { return static_cast<double>(r.sim.verlet_list().builds()); }},
    // The energy balance (dynamics/simulation.hpp, EnergyBalance): at the last force evaluation,
    // one step before `step`; cumulative values count from the run's first step. Before a run's
    // first step nothing has evaluated the forces: the energies of that row are the state's own
    // (the springs at these positions, the particles' motion).
    {"elastic_energy_normal", "J", "stored in the normal springs (linear: sum 1/2 kn overlap^2)",
     [](In r) { return r.e.started ? r.sim.sums().elastic_normal_J : r.c.elastic_normal_J; }},
    {"elastic_energy_tangential", "J", "stored in the tangential springs (linear: sum 1/2 ks |u_s|^2)",
     [](In r) { return r.e.started ? r.sim.sums().elastic_tangential_J : r.c.elastic_tangential_J; }},
    {"kinetic_energy_centred", "J", "translational + rotational, 1/2 m v(n-1/2).v(n+1/2): the kinetic energy of the balance",
     [](In r) {
       return r.e.started ? r.e.kinetic
                          : translational_kinetic_energy(r.sim.particles()) + rotational_kinetic_energy(r.sim.particles());
     }},
    {"work_by_cell", "J", "integral of V sigma:d(eps) since the run started, compression positive", [](In r) { return r.e.work_by_cell; }},
    {"dissipated_by_damping", "J", "since the run started", [](In r) { return r.e.dissipated_damping; }},
    {"dissipated_by_friction", "J", "by sliding contacts since the run started", [](In r) { return r.e.dissipated_friction; }},
    {"energy_closure_error", "1", "|E_in - (E_stored + E_dissipated)| / (E_in + max(0, -E_stored)), E_in = stored energy at the start + work by the cell (E_stored < 0 only with cohesion)",
     [](In r) { return r.e.closure_error(); }},
    {"elastic_energy_rolling", "J", "stored in the rolling springs, sum 1/2 kr |u_r|^2 (0 without rolling resistance)",
     [](In r) { return r.e.started ? r.sim.sums().elastic_rolling_J : r.c.elastic_rolling_J; }},
    {"dissipated_by_rolling", "J", "by rolling resistance at its cap since the run started", [](In r) { return r.e.dissipated_rolling; }},
    {"shear_strain_12", "1", "engineering shear strain since the reference, compression positive (cell/periodic_cell.hpp)",
     [](In r) { return r.cell.shear_strain()[0]; }},
    {"shear_strain_13", "1", "", [](In r) { return r.cell.shear_strain()[1]; }},
    {"shear_strain_23", "1", "", [](In r) { return r.cell.shear_strain()[2]; }},
    {"shear_rate_12", "1/s", "engineering shear strain rate applied in the last step, compression positive",
     [](In r) { return r.sim.rates().shear[0]; }},
    {"shear_rate_13", "1/s", "", [](In r) { return r.sim.rates().shear[1]; }},
    {"shear_rate_23", "1/s", "", [](In r) { return r.sim.rates().shear[2]; }},
    {"cell_tilt_12", "m", "tilt xy of the cell (the x offset of its second vector), within +-L1/2 after re-mapping",
     [](In r) { return r.cell.tilts()[0]; }},
    {"cell_tilt_13", "m", "tilt xz", [](In r) { return r.cell.tilts()[1]; }},
    {"cell_tilt_23", "m", "tilt yz", [](In r) { return r.cell.tilts()[2]; }},
    {"pore_pressure_ratio", "1",
     "control stages: r_u = 1 - p/p0, p0 at the stage start (constant volume: the excess pore pressure ratio); 0 elsewhere",
     [](In r) { return r.where.mean_stress_at_stage_start > 0 ? 1 - r.p / r.where.mean_stress_at_stage_start : 0.0; }},
    {"double_amplitude_strain", "1",
     "control stages with cyclic loading: max - min strain of the cyclic component in the current cycle",
     [](In r) { return r.where.double_amplitude_strain; }},
    {"time_step_over_critical", "1", "time step / the law's critical step as the engine checks it (numerics.max_time_step_fraction)",
     [](In r) { return time_step_over_critical(r.sim); }},
    {"time_step_over_contact_critical", "1",
     "time step / 2 sqrt(m_min / k_max), k_max the stiffest contact's d f_n/d overlap at this row (Hertz: at its largest "
     "overlap); 0 without contacts",
     [](In r) { return time_step_over_contact_critical(r.sim); }},
};

}  // namespace

const std::vector<SeriesColumn>& series_columns() {
  static const std::vector<SeriesColumn> described = describe(columns);
  return described;
}

std::vector<double> measure_row(const Simulation& sim, const RowContext& where) { return measure(columns, RowInputs(sim, where)); }

}  // namespace dem
