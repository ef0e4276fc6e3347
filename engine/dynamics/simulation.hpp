#pragma once
// The simulation: state (particles, cell, contacts), the time step, and one fixed order of
// operations per step:
//
//   1. rebuild the Verlet list if the rebuild criterion says so;
//   2. contact forces at the current positions (velocities from the previous half step);
//      the contact stress and the servo stiffness are summed in the same loop;
//   3. the cell's velocity gradient from its control (servo);
//   4. leapfrog update of velocities (with damping) and fractional positions;
//   5. homogeneous deformation of the cell, re-mapped when a tilt passes half a length.
//
// The contact law (contact/contact_law.hpp) and the damping form are chosen once, when the
// simulation is built; the per-step loop is a monomorphic template (see dynamics/kernel.hpp),
// compiled twice: for an orthorhombic cell and for one that is tilted or shearing. Each step runs
// the first while the cell has no tilt and no shear rate, so a scene that never shears pays
// nothing for shear.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>

#include "cell/periodic_cell.hpp"
#include "contact/contact_history.hpp"
#include "contact/contact_law.hpp"
#include "control/stress_servo.hpp"
#include "core/particles.hpp"
#include "neighbour/verlet_list.hpp"

namespace dem {

struct Material {
  double density_kg_per_m3 = 2650;
  AnyContactLaw law = linear_law(1e6, 1e6, 0.5);  // the kernel is compiled for the law chosen
};

// docs/method.md#damping. Viscous: body force -c v on the fluctuating velocity with c = 2 C_t sqrt(kn m),
// torque -c_r omega with c_r = 2 C_r sqrt(kn r^2 I) (the rotational analogue), kn the law's
// damping stiffness (a law without one, Hertz's, needs local damping). Local: Cundall's
// non-viscous damping, each force component reduced by alpha |F_k| opposing the velocity.
struct Damping {
  enum class Form { Viscous, Local };
  Form form = Form::Viscous;
  double translational = 0.05;  // C_t (viscous: fraction of critical) or alpha (local) [-]
  double rotational = 0.05;     // C_r [-]
};

// Thrown when a value becomes non-finite; the message names the step.
struct NonFiniteError : std::runtime_error {
  using std::runtime_error::runtime_error;
};


struct PairForces;  // dynamics/kernel.hpp

struct StepSums {          // by-products of the last force evaluation
  Mat3 stress_Pa = Mat3::Zero();       // (1/V) sum_c f_c (x) l_c, symmetrised, compression positive
  Vec3 stiffness_Pa = Vec3::Zero();    // servo stiffness K_k
  std::size_t contacts = 0;            // pairs in contact
  double sum_normal_force_N = 0;
  double elastic_normal_J = 0;         // sum 1/2 kn overlap^2
  double elastic_tangential_J = 0;     // sum 1/2 ks |u_s|^2 (after the Coulomb cap)
  double friction_loss_J = 0;          // spring energy removed by the Coulomb cap (and by contacts opening) in this evaluation
  double elastic_rolling_J = 0;        // sum 1/2 kr |u_r|^2 (rolling resistance)
  double rolling_loss_J = 0;           // rolling spring energy removed by its cap (and by contacts opening)
  double contact_damping_loss_J = 0;   // taken by the contact dashpots in this step (laws with dashpots)
};

// The energy balance of a run [J], accumulated step by step from the first step of this
// Simulation (or of its restore). Energies are those of the last force evaluation, time t_n:
// kinetic energy is the time-centred 1/2 m v(n-1/2).v(n+1/2), which with elastic energy at x_n
// makes the leapfrog energy error O(dt^2) (exactly conserved for linear springs); the cell's work
// is the trapezoidal sum of V sigma : G dt between force evaluations (axes, and shears when the
// cell shears).
struct EnergyBalance {
  double work_by_cell = 0;         // integral of V sigma : d(eps), compression positive
  double dissipated_damping = 0;   // taken by the damping: body (translational + rotational) and contact dashpots
  double dissipated_friction = 0;  // taken by sliding contacts
  double dissipated_rolling = 0;   // taken by rolling resistance at its cap
  double kinetic = 0;              // time-centred, translational + rotational
  double elastic = 0;              // normal + tangential + rolling
  double stored_at_start = 0;      // kinetic + elastic at the first step
  Vec3 virial = Vec3::Zero();      // V sigma_kk at the last evaluation [J]
  Vec3 shear_virial = Vec3::Zero();  // V sigma_xy, V sigma_xz, V sigma_yz at the last evaluation [J]
  bool started = false;
  double stored() const { return kinetic + elastic; }
  double energy_in() const { return stored_at_start + work_by_cell; }
  // |energy in - (stored + dissipated)| / (energy in + what a negative store has released); 0 while
  // nothing has been put in. Stored energy is below zero only with cohesion (a cohesive contact's
  // potential is negative, contact/linear_cohesive.hpp): the contacts then give out energy that the
  // damping takes, with the cell's work near zero or negative, and the energy in alone would make
  // any gap look large (a 2e-8 J gap against 1e-4 J passed through read as 143 %). Without cohesion
  // the stored energy is >= 0 and the measure is |gap| / energy in, as it always was.
  double closure_error() const {
    const double in = energy_in() + std::max(0.0, -stored());
    return in > 0 ? std::abs(energy_in() - stored() - dissipated_damping - dissipated_friction - dissipated_rolling) / in : 0.0;
  }
};

class Simulation {
 public:
  Simulation(Particles particles, PeriodicCell cell, Material material, Damping damping, double time_step_s,
             double verlet_skin_m);
  ~Simulation();
  Simulation(Simulation&&) noexcept;
  Simulation& operator=(Simulation&&) noexcept;

  void step(const CellTargets& targets, const ServoSettings& servo);
  // The same with a servo that learns the packing's stiffness (stress stages and paths).
  void step(const CellTargets& targets, AdaptiveServo& servo);
  // Every component of the cell's velocity gradient (control_error(control) must be "").
  void step(const CellControl& control, AdaptiveServo& servo);
  void step(const CellControl& control, const ServoSettings& servo);

  const Particles& particles() const { return particles_; }
  const PeriodicCell& cell() const { return cell_; }
  PeriodicCell& cell() { return cell_; }
  const PairList& pairs() const { return list_.pairs(); }
  const ContactHistory& history() const { return history_; }  // per pair of pairs()
  const VerletList& verlet_list() const { return list_; }
  const Material& material() const { return material_; }
  const Damping& damping() const { return damping_; }
  double time_step() const { return dt_; }
  std::int64_t step_count() const { return step_; }
  double time() const { return static_cast<double>(step_) * dt_; }
  const Vec3& strain_rate() const { return rates_.axial; }  // applied in the last step [1/s]
  const CellRates& rates() const { return rates_; }         // the velocity gradient applied in the last step
  // Whether the cell is re-mapped when a tilt passes half a length (on by default; off to compare
  // a run with its re-mapped twin, or for tilts that stay small).
  void set_cell_remapping(bool on) { remap_cell_ = on; }
  std::size_t cell_remaps() const { return cell_remaps_; }
  const StepSums& sums() const { return sums_; }
  const std::vector<Vec3>& net_force() const { return force_; }  // from the last force evaluation [N]
  double kinetic_energy() const { return kinetic_energy_; }      // translational, fluctuating, after the last step [J]
  // The balance after the last step (with contact dashpots, their work of that step booked).
  EnergyBalance energy() const;

  // Restores the dynamic state saved by a previous run (for a bit-for-bit continuation). A history
  // of another kind than this law keeps (none, another tangential law) starts unloaded.
  void restore(std::int64_t step, const CellRates& rates, PairList contacts, const ContactHistory& history);
  // Restores a checkpoint of this same run (run/checkpoint.hpp): also the whole Verlet list, its
  // history and the energy balance, so that rows, rebuilds and sums continue exactly as without the stop.
  void restore_checkpoint(std::int64_t step, const CellRates& rates, VerletList::Saved list, const ContactHistory& history,
                          const EnergyBalance& energy);

  // Internal: the per-step kernel, chosen once from the material and damping.
  struct Kernel;

 private:
  template <class Law, class DampingPolicy>
  friend struct KernelImpl;
  void adopt(const ContactHistory& history);  // `history` if of this law's kinds, else unloaded
  // One step, the fixed order above; `rates` is called after the force evaluation.
  void advance(const std::function<CellRates()>& rates);
  void remap_cell();
  Particles particles_;
  PeriodicCell cell_;
  Material material_;
  Damping damping_;
  double dt_;
  VerletList list_;
  ContactHistory history_;
  std::int64_t step_ = 0;
  CellRates rates_;
  bool remap_cell_ = true;
  std::size_t cell_remaps_ = 0;
  StepSums sums_;
  std::unique_ptr<PairForces> pair_forces_;  // per-pair forces of the last evaluation
  std::vector<Vec3> force_;
  double kinetic_energy_ = 0;
  EnergyBalance energy_;
  std::unique_ptr<Kernel> kernel_;
  bool contact_dashpots_ = false;  // the law has contact dashpots: their dissipation's second half each step
  // The last step's second half of the dashpots' work is not in energy_ yet: the next step's pair
  // loop books it (it has the velocities in hand), or dashpot_second_half before the pair list
  // changes; energy() adds it to what it returns. Both give the same bits.
  bool dashpot_half_pending_ = false;
  // H(n) H(n+1)^-1 of the last step's deformation, before any remap (PreviousHalf::back): the
  // dashpots' pending half rebuilds its evaluation's branch vectors with it.
  Mat3 cell_back_ = Mat3::Identity();
  void book_pending_dashpot_half();
};

}  // namespace dem
