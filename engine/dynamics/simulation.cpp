#include "dynamics/simulation.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <type_traits>

#include "dynamics/kernel.hpp"
#include "dynamics/kernel_simd.hpp"

namespace dem {

StepSums total_of_chunks(const std::vector<StepSums>& chunk_sums, const PeriodicCell& cell) {
  StepSums total;
  for (const StepSums& chunk : chunk_sums) {
    total.stress_Pa += chunk.stress_Pa;
    total.stiffness_Pa += chunk.stiffness_Pa;
    total.contacts += chunk.contacts;
    total.sum_normal_force_N += chunk.sum_normal_force_N;
    total.elastic_normal_J += chunk.elastic_normal_J;
    total.elastic_tangential_J += chunk.elastic_tangential_J;
    total.friction_loss_J += chunk.friction_loss_J;
    total.elastic_rolling_J += chunk.elastic_rolling_J;
    total.rolling_loss_J += chunk.rolling_loss_J;
    total.contact_damping_loss_J += chunk.contact_damping_loss_J;
  }
  const double inv_volume = 1.0 / cell.volume();
  const Mat3 stress = total.stress_Pa;  // a copy: (A + A^T) assigned to A would alias
  total.stress_Pa = 0.5 * (stress + stress.transpose()) * inv_volume;
  total.stiffness_Pa *= inv_volume;
  return total;
}

MotionSums total_of_chunks(const std::vector<MotionSums>& chunk_sums, bool wrapped) {
  MotionSums total;
  for (const MotionSums& chunk : chunk_sums) {
    total.kinetic_half_step += chunk.kinetic_half_step;
    total.kinetic_centred += chunk.kinetic_centred;
    total.damping_loss += chunk.damping_loss;
    total.max_speed2 = std::max(total.max_speed2, chunk.max_speed2);
  }
  total.kinetic_half_step = wrapped ? 0.5 * total.kinetic_half_step : std::nan("");
  total.kinetic_centred *= 0.5;
  total.damping_loss *= 0.5;
  return total;
}

struct Simulation::Kernel {
  virtual ~Kernel() = default;
  // Forces (into sims.sums_ and the pair forces) and the update of one step; `book_previous_half`:
  // also the second half of the step before's dashpot work (forces_and_motion, with cell_back_).
  virtual MotionSums step(Simulation& sim, bool book_previous_half) = 0;
  // Laws with contact dashpots: the second half of their dissipation in the step just taken [J]
  // (dashpot_second_half); 0 for the other laws.
  virtual double dashpot_second_half(const Simulation& sim) const = 0;
};

template <class Law, class DampingPolicy>
struct KernelImpl final : Simulation::Kernel {
  Law law;
  DampingPolicy damping;
  int simd = simd_width();  // the same result at any width; wider is faster
  KernelImpl(Law l, DampingPolicy d) : law(l), damping(std::move(d)) {}
  MotionSums step(Simulation& s, bool book_previous_half) override {
    // The sheared loops when the cell is tilted or shearing (with zero tilts they give the
    // orthorhombic loops' bits).
    if (s.cell_.sheared() || s.rates_.shears()) return step_as<true>(s, book_previous_half);
    return step_as<false>(s, book_previous_half);
  }
  double dashpot_second_half(const Simulation& s) const override {
    if constexpr (Law::damped) {
      return dem::dashpot_second_half<Law>(simd, s.particles_, s.cell_, s.list_.pairs(), s.list_.index(), *s.pair_forces_, s.rates_,
                                            s.cell_back_, s.dt_);
    } else {
      return 0.0;
    }
  }
  template <bool Sheared>
  MotionSums step_as(Simulation& s, bool book_previous_half) {
    if constexpr (Law::dashpot_per_pair) {
      if (s.pair_forces_->dashpot_list != s.list_.changes())
        dashpot_coefficients(law, s.particles_, s.list_.pairs(), s.dt_, s.list_.changes(), *s.pair_forces_);
    }
    return forces_and_motion<Law, DampingPolicy, Sheared>(simd, law, damping, s.particles_, s.cell_, s.list_.pairs(),
                                                          s.history_, s.list_.index(), s.rates_, s.dt_, *s.pair_forces_,
                                                          s.sums_, s.force_, PreviousHalf{book_previous_half, s.cell_back_});
  }
};

namespace {
template <class Law>
std::unique_ptr<Simulation::Kernel> make_kernel(const Law& law, const Particles& p, const Damping& d, double dt) {
  if (d.form == Damping::Form::Local)
    return std::make_unique<KernelImpl<Law, LocalDamping>>(law, LocalDamping(p, d, 0, dt));
  const double k = law.normal.damping_stiffness();
  if (!(k > 0) && (d.translational > 0 || d.rotational > 0))
    throw std::invalid_argument("viscous damping needs a contact stiffness to scale with, and this contact law has none: "
                                "use damping.form: local");
  return std::make_unique<KernelImpl<Law, ViscousDamping>>(law, ViscousDamping(p, d, k, dt));
}

// An empty history shaped by the law: what it keeps per contact.
ContactHistory history_for(const AnyContactLaw& law) {
  ContactHistory h;
  h.tangential_name = tangential_history_name(law);
  h.rolling_on = has_rolling(law);
  return h;
}
}  // namespace

Simulation::Simulation(Particles particles, PeriodicCell cell, Material material, Damping damping, double time_step_s,
                       double verlet_skin_m)
    : particles_(std::move(particles)),
      cell_(cell),
      material_(material),
      damping_(damping),
      dt_(time_step_s),
      list_(verlet_skin_m),
      history_(history_for(material.law)),
      pair_forces_(std::make_unique<PairForces>()) {
  kernel_ = std::visit([&](const auto& law) { return make_kernel(law, particles_, damping_, dt_); }, material_.law);
  contact_dashpots_ = contact_damping_ratio(material_.law) > 0;
}

Simulation::~Simulation() = default;
Simulation::Simulation(Simulation&&) noexcept = default;
Simulation& Simulation::operator=(Simulation&&) noexcept = default;

void Simulation::adopt(const ContactHistory& history) {
  const std::size_t n = list_.pairs().size();
  history_ = history_for(material_.law);
  history_.reset(n);
  if (history_.has_tangential() && history.tangential_name == history_.tangential_name && history.tangential.size() == n)
    history_.tangential = history.tangential, history_.sliding = history.sliding;
  if (history_.rolling_on && history.rolling_on && history.rolling.size() == n) history_.rolling = history.rolling;
}

void Simulation::restore(std::int64_t step, const CellRates& rates, PairList contacts, const ContactHistory& history) {
  book_pending_dashpot_half();
  step_ = step;
  rates_ = rates;
  list_.restore(std::move(contacts));
  adopt(history);
}

void Simulation::restore_checkpoint(std::int64_t step, const CellRates& rates, VerletList::Saved list,
                                    const ContactHistory& history, const EnergyBalance& energy) {
  step_ = step;
  rates_ = rates;
  list_.restore_exact(std::move(list), particles_);
  adopt(history);
  energy_ = energy;  // saved by energy(): the work of its last step in it
  dashpot_half_pending_ = false;
}

EnergyBalance Simulation::energy() const {
  EnergyBalance e = energy_;
  if (dashpot_half_pending_) e.dissipated_damping += kernel_->dashpot_second_half(*this);
  return e;
}

void Simulation::book_pending_dashpot_half() {
  if (!dashpot_half_pending_) return;
  energy_.dissipated_damping += kernel_->dashpot_second_half(*this);
  dashpot_half_pending_ = false;
}

void Simulation::step(const CellTargets& targets, const ServoSettings& servo) {
  advance([&] { return CellRates{servo_strain_rates(targets, sums_.stress_Pa, sums_.stiffness_Pa, servo, dt_), Vec3::Zero()}; });
}

void Simulation::step(const CellTargets& targets, AdaptiveServo& servo) {
  advance([&] { return CellRates{servo.rates(targets, sums_.stress_Pa, sums_.stiffness_Pa, dt_), Vec3::Zero()}; });
}

void Simulation::step(const CellControl& control, AdaptiveServo& servo) {
  advance([&] { return servo.rates(control, sums_.stress_Pa, sums_.stiffness_Pa, dt_); });
}

void Simulation::step(const CellControl& control, const ServoSettings& servo) {
  advance([&] { return servo_rates(control, sums_.stress_Pa, sums_.stiffness_Pa, servo, dt_); });
}

void Simulation::remap_cell() {
  const PeriodicCell before = cell_;
  if (!cell_.remap()) return;
  for (Vec3& s : particles_.s) s = cell_.remapped(before, s);
  list_.invalidate();  // the same pairs, at other fractional positions: rebuilt at the next step
  ++cell_remaps_;
}

void Simulation::advance(const std::function<CellRates()>& rates) {
  if (list_.rebuild_due(particles_, cell_)) {
    book_pending_dashpot_half();  // on the list its forces were stored for
    list_.build(particles_, cell_, &history_);
  }
  const bool book_previous_half = dashpot_half_pending_;
  const MotionSums motion = kernel_->step(*this, book_previous_half);
  if (book_previous_half) {  // the step before's last term, booked by this loop: the order of the sum as before
    double previous = 0;  // the chunks' sums in chunk order, as dashpot_second_half adds them
    for (const double chunk : pair_forces_->previous_dashpot_sums) previous += chunk;
    energy_.dissipated_damping += 0.5 * dt_ * previous;
    dashpot_half_pending_ = false;
  }
  if (!sums_.stress_Pa.allFinite()) {
    std::ostringstream msg;
    msg << "non-finite contact stress at step " << step_ << " (time " << time() << " s)";
    throw NonFiniteError(msg.str());
  }
  // The cell's work over the last step, trapezoidal in V sigma (the rate is the one applied since
  // the previous evaluation).
  const Vec3 virial = sums_.stress_Pa.diagonal() * cell_.volume();
  const Mat3& sigma = sums_.stress_Pa;
  const Vec3 shear_virial = Vec3(sigma(0, 1), sigma(0, 2), sigma(1, 2)) * cell_.volume();
  if (energy_.started) {
    energy_.work_by_cell += 0.5 * dt_ * rates_.axial.dot(virial + energy_.virial);
    if (rates_.shears()) energy_.work_by_cell += 0.5 * dt_ * rates_.shear.dot(shear_virial + energy_.shear_virial);
  }
  energy_.virial = virial;
  energy_.shear_virial = shear_virial;
  energy_.elastic = sums_.elastic_normal_J + sums_.elastic_tangential_J + sums_.elastic_rolling_J;
  energy_.dissipated_friction += sums_.friction_loss_J;
  energy_.dissipated_rolling += sums_.rolling_loss_J;
  rates_ = rates();  // the update does not depend on them: they apply from the next step
  list_.add_motion(dt_ * std::sqrt(motion.max_speed2));
  kinetic_energy_ = motion.kinetic_half_step;
  energy_.kinetic = motion.kinetic_centred;
  energy_.dissipated_damping += motion.damping_loss;
  // The contact dashpots' share (+0.0 for a law without, which leaves the sum's bits as they were),
  // and for a law with them the half with the new velocities and the new cell rates: booked by
  // the next step's pair loop, or before the list changes, or added by energy().
  energy_.dissipated_damping += sums_.contact_damping_loss_J;
  dashpot_half_pending_ = contact_dashpots_;
  if (!energy_.started) energy_.stored_at_start = energy_.stored(), energy_.started = true;
  if (!std::isfinite(kinetic_energy_)) {
    std::ostringstream msg;
    msg << "non-finite kinetic energy or a particle moving more than a cell in one step at step " << step_ << " (time "
        << time() << " s): the run is unstable (time step too large for the stiffness?)";
    throw NonFiniteError(msg.str());
  }
  if (contact_dashpots_) {  // their pending half rebuilds this evaluation's branch vectors (PreviousHalf)
    const Mat3 evaluated = cell_.matrix();
    cell_.deform(rates_, dt_);
    cell_back_ = evaluated * cell_.matrix().inverse();  // before a remap: a branch vector is the same in either
  } else {
    cell_.deform(rates_, dt_);
  }
  if (remap_cell_ && cell_.sheared()) remap_cell();
  ++step_;
}

}  // namespace dem
