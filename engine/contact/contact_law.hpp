#pragma once
// A contact law: a normal law, a tangential law and a rolling law, each a value type that owns
// its force, its stored energy, what the servo and the time step need, and (tangential and
// rolling) the history it keeps per contact. Every part is written once, for any lanes `O`
// (contact/lane_ops.inc), and called by the scalar and the vectorised pair loops
// (dynamics/kernel_simd_pairs.inc) and by the measurements.
//
// What each part provides (see contact/linear_spring.hpp for the exemplar):
//   normal      force<O>(overlap, R*), stiffness<O>(overlap, R*) (d f_n / d overlap, for the servo),
//               energy<O>(f_n, overlap), critical_time_step(m_min, r_min, density) and its formula,
//               damping_stiffness() (0: viscous damping cannot be scaled), needs_reduced_radius,
//               friction_normal_force<O>(f_n) (the normal force the Coulomb and rolling caps take),
//               needs_normal_velocity: if true, also damping_force<O>(overlap, R*, d overlap/dt, m*)
//               (added to f_n), its normal_coefficient<O>(overlap, R*, m*), and
//               tangential_coefficient<O>(k_t, m*) (a tangential dashpot while the contact sticks;
//               see contact/contact_dashpot.hpp); optionally constant_stiffness = true
//   tangential  has_tangential, history_name / history_unit, needs_reduced_radius, optionally
//               constant_stiffness = true (stiffness<O> for a tangential dashpot),
//               update<O>(HistoryStep&, f_n, overlap, R*, touch), energy<O>(f_t, overlap, R*),
//               opening_loss<O>(|history|^2), force_of<O>(history, overlap, R*)
//   rolling     has_rolling, update<O>(HistoryStep&, f_n, touch), energy<O>(f_r), opening_loss<O>
// and, each part, its scene keys (contact/parameter.hpp): `parameters`, `from`, `write`, and
// `law_name` (an elastic normal part) or `switched_by` (a part a key turns on).
//
// To add a law: write its parts in a header here (their keys with them) and add the combination
// to AnyContactLaw below. config/contact_keys.cpp reads, documents and writes the keys of every
// alternative from the parts' declarations; the kernels are instantiated for every alternative
// (dynamics/kernel_simd.cpp, dynamics/simulation.cpp), and the tests enumerate them
// (tests/engine/dynamics/packing_support.hpp).
#include <string>
#include <variant>

#include "contact/contact_dashpot.hpp"
#include "contact/hertz_mindlin.hpp"
#include "contact/linear_cohesive.hpp"
#include "contact/linear_spring.hpp"
#include "contact/rolling.hpp"
#include "core/particles.hpp"

namespace dem {

// No tangential force: the kernel has no tangential spring, no history and no torque.
struct NoFriction {
  static constexpr bool has_tangential = false;
  static constexpr bool needs_reduced_radius = false;
};

// Whether a part's stiffness<O> is a constant (it says so with constant_stiffness = true).
template <class Part>
constexpr bool constant_stiffness() {
  if constexpr (requires { Part::constant_stiffness; }) {
    return Part::constant_stiffness;
  } else {
    return false;
  }
}

template <class Normal, class Tangential = NoFriction, class Rolling = NoRolling>
struct ContactLaw {
  Normal normal{};
  Tangential tangential{};
  Rolling rolling{};

  using NormalLaw = Normal;
  using TangentialLaw = Tangential;
  using RollingLaw = Rolling;
  static constexpr bool has_tangential = Tangential::has_tangential;
  static constexpr bool has_rolling = Rolling::has_rolling;
  static constexpr bool rotates = has_tangential || has_rolling;  // torques, spins
  static constexpr bool damped = Normal::needs_normal_velocity;   // contact dashpots
  // Contact dashpots whose coefficients c_n and c_t depend on the two masses only (constant
  // stiffnesses): computed once per pair list instead of every step (dynamics/kernel.hpp).
  static constexpr bool dashpot_per_pair =
      damped && constant_stiffness<Normal>() && (!has_tangential || constant_stiffness<Tangential>());
  static constexpr bool needs_reduced_radius =
      Normal::needs_reduced_radius || Tangential::needs_reduced_radius || has_rolling;
};

using LinearLaw = ContactLaw<LinearNormal>;
using LinearFrictionLaw = ContactLaw<LinearNormal, LinearCoulomb>;
using LinearRollingLaw = ContactLaw<LinearNormal, LinearCoulomb, RollingSpring>;
using HertzLaw = ContactLaw<HertzNormal>;
using HertzMindlinLaw = ContactLaw<HertzNormal, MindlinCoulomb>;
using HertzMindlinRollingLaw = ContactLaw<HertzNormal, MindlinCoulomb, RollingSpring>;
using LinearDashpotLaw = ContactLaw<Dashpot<LinearNormal>>;
using LinearFrictionDashpotLaw = ContactLaw<Dashpot<LinearNormal>, LinearCoulomb>;
using HertzMindlinDashpotLaw = ContactLaw<Dashpot<HertzNormal>, MindlinCoulomb>;
using LinearCohesiveLaw = ContactLaw<LinearCohesiveNormal>;
using LinearCohesiveFrictionLaw = ContactLaw<LinearCohesiveNormal, LinearCoulomb>;

// Every law a scene can choose; the kernels are compiled for each.
using AnyContactLaw = std::variant<LinearLaw, LinearFrictionLaw, LinearRollingLaw, HertzLaw, HertzMindlinLaw, HertzMindlinRollingLaw,
                                   LinearDashpotLaw, LinearFrictionDashpotLaw, HertzMindlinDashpotLaw, LinearCohesiveLaw,
                                   LinearCohesiveFrictionLaw>;

// The linear law with Coulomb friction if mu > 0 (frictionless otherwise).
AnyContactLaw linear_law(double kn, double ks, double mu);

bool has_tangential(const AnyContactLaw& law);
bool has_rolling(const AnyContactLaw& law);
double friction_coefficient(const AnyContactLaw& law);  // mu; 0 without friction
// The name of the tangential history ("tangential_spring", "tangential_force"); empty without friction.
std::string tangential_history_name(const AnyContactLaw& law);
// The critical time step of the law on these particles [s], and how it is computed.
double critical_time_step(const AnyContactLaw& law, const Particles& p, double density_kg_per_m3);
std::string critical_time_step_formula(const AnyContactLaw& law);
double damping_stiffness(const AnyContactLaw& law);  // [N/m]; 0 if the law has none
double contact_damping_ratio(const AnyContactLaw& law);  // zeta of the contact dashpots; 0 without
std::string law_name(const AnyContactLaw& law);          // the scene's material.law

}  // namespace dem
