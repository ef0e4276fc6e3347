#pragma once
// Measurements of a simulation state. Pure functions: they read a const state and never change a
// trajectory. Compression positive.
#include <cstddef>
#include <vector>

#include "dynamics/simulation.hpp"

namespace dem {

double void_ratio(const Particles& p, const PeriodicCell& cell);          // (V - Vs) / Vs, overlaps not subtracted
double coordination_number(std::size_t contacts, std::size_t particles);  // 2 Nc / Np (rattlers included)

struct ContactCounts {
  std::size_t contacts = 0;               // Nc
  std::size_t sliding = 0;                // Ns (|f_t| at the Coulomb limit at the last force evaluation)
  std::size_t particles_no_contact = 0;   // N0
  std::size_t particles_one_contact = 0;  // N1
  Mat3 stress_Pa = Mat3::Zero();          // (1/V) sum_c f_c (x) l_c, symmetrised, compression positive
  double mean_normal_force_N = 0;
  std::vector<Vec3> normals;              // unit normal of each contact (filled if asked for)
  std::vector<double> normal_forces_N;    // f_n of each contact (filled if asked for)
  // The contact network (filled if asked for): per contact, its two particles, |f_t| and the
  // branch vector from the first particle's centre to the second's (m).
  std::vector<std::int64_t> pairs;        // i, j of each contact
  std::vector<double> tangential_forces_N;
  std::vector<Vec3> branches;
  // The energy the contacts' springs hold at these positions, by the law's own energy functions
  // [J]: what the time series reports before the first force evaluation of a run (row 0).
  double elastic_normal_J = 0, elastic_tangential_J = 0, elastic_rolling_J = 0;
};
// Surveys the contacts at the current positions: counts, and the stress from the contact law's
// normal force plus the tangential force its stored history stands for. Evaluated at the state of
// the row (one position update after the last force evaluation), by the law's own functions, so
// it can be called at any time without touching the trajectory.
ContactCounts count_contacts(const Simulation& sim, bool keep_normals = false, bool keep_network = false);

// Mechanical coordination number without rattlers (Thornton 2000): (2 Nc - N1) / (Np - N0 - N1).
double mechanical_coordination_number(const ContactCounts& c, std::size_t particles);

// Mean |net force on a particle| / mean normal contact force, from the last force evaluation.
// The normal force is used as the mean contact force; since |f| >= f_n this errs on the high side.
double unbalanced_force_ratio(const Simulation& sim);

// The contact dashpots' step number dt max_i sum_c max(c_n, c_t) / m_i over the contacts at the
// current positions (contact/contact_dashpot.hpp: c = 2 zeta sqrt(m* k)), 0 for a law without them.
// The dashpot force is taken from the speed of the previous half step, an explicit update: a
// sphere whose Z neighbours move against it (v_j = -v_i) sees its velocity multiplied each step by
// 1 - 2 dt sum_c c_c / m_i along a direction where every contact's damping acts (c_n = c_t when
// ks = kn), which is unstable once that passes -1, i.e. once this number passes 1, whatever the
// one-contact critical step says (it is computed for a single contact).
double dashpot_step_number(const Simulation& sim);

// The time step over the law's critical step as the engine checks it (critical_time_step,
// contact/contact_law.hpp; the lightest sphere and the law's constants).
double time_step_over_critical(const Simulation& sim);
// The time step over the leapfrog limit of the stiffest contact at the current positions,
// 2 sqrt(m_min / k_max) (times sqrt(1 + zeta^2) - zeta with contact dashpots), k_max the largest
// tangent normal stiffness d f_n / d overlap of the contacts: the linear laws' critical step again
// (k = kn), and for Hertz (k_n = 2 E* sqrt(R* overlap)) the limit at the largest overlap, which
// Rayleigh's step does not see. 0 without contacts.
double time_step_over_contact_critical(const Simulation& sim);

double translational_kinetic_energy(const Particles& p);  // of the fluctuating velocities [J]
double rotational_kinetic_energy(const Particles& p);     // [J]

double mean_diameter(const Particles& p);  // [m]

// The largest rate of the cell's deformation: max over all six components of |rate|, the three
// axial strain rates and the three engineering shear strain rates (simple shear at rate g has
// the shear rate g of the inertial number's definition, GDR MiDi 2004). [1/s]
double max_strain_rate(const CellRates& rates);

// Inertial number I = max_strain_rate d_mean sqrt(rho / p) with the last applied rates (every
// component, shear included) and the mean stress p given; 0 if p <= 0.
double inertial_number(const Simulation& sim, double p_Pa);

// Above this the loading is not quasi-static (GDR MiDi 2004: I < 1e-3); a stage warns when a
// stress path's leg or a control stage goes above it.
inline constexpr double quasi_static_inertial_number = 1e-3;

double mean_stress(const Mat3& stress_Pa);        // p = tr(sigma) / 3
double deviator_stress(const Mat3& stress_Pa);    // q = sqrt(((s1-s2)^2 + (s2-s3)^2 + (s1-s3)^2) / 2), principal values

}  // namespace dem
