#pragma once
// Contact dashpots: a viscous force in each contact, a fraction zeta of the critical damping of the
// two-body oscillator the contact makes (Cundall & Strack 1979's contact damping; docs/method.md#open-choices's
// alternative to body damping):
//   normal:     f_n = f_e(overlap) + c_n d(overlap)/dt,   c_n = 2 zeta sqrt(m* k_n),
//   tangential: f_t = f_spring - c_t v_t while the contact sticks, 0 while it slides (the shear
//               dashpot of PFC's linear model, Itasca PFC 6 manual, "Linear Model", slip mode),
//               c_t = 2 zeta sqrt(m* k_t),
// with m* = m_i m_j / (m_i + m_j), k_n and k_t the elastic parts' tangent stiffnesses.
//
// Linear law: k_n = kn, k_t = ks are constants, and a head-on collision rebounds with the
// coefficient of restitution e = exp(-pi zeta / sqrt(1 - zeta^2)) at any speed.
// Hertz: k_n = 2 E* sqrt(R* overlap) = 3/2 K overlap^1/2 (f_e = K overlap^3/2), so
// c_n = 2 sqrt(3/2) zeta sqrt(m* K) overlap^1/4: the dashpot of Tsuji, Tanaka & Ishida (1992,
// Powder Technol. 71, 239), alpha sqrt(m* K) overlap^1/4 with alpha = 2 sqrt(3/2) zeta, which gives
// a restitution independent of the impact speed; it is LAMMPS pair granular's `damping tsuji`
// (there alpha is computed from e). The tangential dashpot takes Mindlin's k_t = 8 G* sqrt(R* overlap).
//
// The normal force the Coulomb cap uses is the total, clipped at zero (a contact that the dashpot
// pulls carries no friction); LAMMPS takes |f_n| (its get_fncrit), which would grow a cap under pull.
// No clipping of f_n itself (LAMMPS's `limit_damping`): the contact ends when the overlap does, and
// the closed-form restitution above holds for exactly that. The dashpot's dissipation,
// c_n (d overlap/dt)^2 dt + c_t |v_t|^2 dt in each step, is booked with the damping of the energy
// balance (dynamics/simulation.hpp).
#include <cmath>
#include <string>

#include "contact/parameter.hpp"

namespace dem {

// A normal part with a dashpot in parallel with the elastic normal part `Elastic`.
template <class Elastic>
struct Dashpot : Elastic {
  double damping_ratio = 0;  // zeta: c = 2 zeta sqrt(m* k), a fraction of critical damping [-]

  // Scene keys (contact/parameter.hpp): the elastic part's and contact_damping, which turns the
  // dashpots on. Open at 1: the closed forms above are for an underdamped contact.
  static constexpr Parameter contact_damping_key{
      "contact_damping", "", 0, 1, false, true, 0.0,
      "contact dashpots, fraction zeta of critical: c_n = 2 zeta sqrt(m* k_n), c_t = 2 zeta sqrt(m* k_t) while sticking; 0 = none"};
  static constexpr const char* law_name = Elastic::law_name;
  static constexpr const char* switched_by = contact_damping_key.name;
  static constexpr auto parameters = joined(Elastic::parameters, std::array{contact_damping_key});
  static Dashpot from(const ParameterValues& v) { return {Elastic::from(v), v.at(contact_damping_key.name)}; }
  void write(ParameterValues& v) const { Elastic::write(v), v[contact_damping_key.name] = damping_ratio; }

  // The pair loop computes the closing speed d(overlap)/dt and the reduced mass m* for this part.
  static constexpr bool needs_normal_velocity = true;

  // c_n = 2 zeta sqrt(m* k_n) [kg/s]; damping_force is c_n d(overlap)/dt [N] (repulsive while the
  // contact closes). Lanes out of contact are dropped by the loop.
  template <class O>
  [[gnu::always_inline]] inline typename O::Real normal_coefficient(typename O::Real overlap, typename O::Real reduced_radius,
                                                                    typename O::Real reduced_mass) const {
    return O::splat(2 * damping_ratio) * O::sqrt(reduced_mass * this->template stiffness<O>(overlap, reduced_radius));
  }
  template <class O>
  [[gnu::always_inline]] inline typename O::Real damping_force(typename O::Real overlap, typename O::Real reduced_radius,
                                                               typename O::Real closing_speed, typename O::Real reduced_mass) const {
    return normal_coefficient<O>(overlap, reduced_radius, reduced_mass) * closing_speed;
  }
  // The tangential dashpot's coefficient c_t = 2 zeta sqrt(m* k_t) [kg/s], k_t the tangential law's stiffness.
  template <class O>
  [[gnu::always_inline]] inline typename O::Real tangential_coefficient(typename O::Real tangential_stiffness,
                                                                        typename O::Real reduced_mass) const {
    return O::splat(2 * damping_ratio) * O::sqrt(reduced_mass * tangential_stiffness);
  }
  // The normal force the Coulomb cap takes: the total, clipped at zero.
  template <class O>
  [[gnu::always_inline]] inline typename O::Real friction_normal_force(typename O::Real fn) const {
    return O::select(O::greater(fn, O::zero()), fn, O::zero());
  }
  // The central-difference limit with damping, (2 / omega) (sqrt(1 + zeta^2) - zeta) (Belytschko,
  // Liu & Moran 2000, Nonlinear Finite Elements, section 6.3.2), on the elastic part's limit.
  double critical_time_step(double m_min_kg, double r_min_m, double density) const {
    return Elastic::critical_time_step(m_min_kg, r_min_m, density) * damped_factor();
  }
  std::string critical_time_step_formula() const {
    return std::string(Elastic::critical_time_step_formula()) + " times sqrt(1 + zeta^2) - zeta (contact dashpots)";
  }
  double damped_factor() const { return std::sqrt(1 + damping_ratio * damping_ratio) - damping_ratio; }
};

}  // namespace dem
