#include "dynamics/simulation.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <type_traits>

#include "dynamics/kernel.hpp"
#include "dynamics/kernel_simd.hpp"

namespace dem {

double critical_time_step(const Particles& p, double kn_N_per_m) {
  if (p.size() == 0) throw std::invalid_argument("critical_time_step: no particles");
  const double m_min = *std::min_element(p.mass.begin(), p.mass.end());
  return 2.0 * std::sqrt(m_min / kn_N_per_m);
}

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
  virtual void forces(Simulation& sim) = 0;
  virtual MotionSums integrate(Simulation& sim) = 0;
};

template <class Friction, class DampingPolicy>
struct KernelImpl final : Simulation::Kernel {
  LinearSpring<Friction> law;
  DampingPolicy damping;
  int simd = simd_width();  // the same result at any width; wider is faster
  KernelImpl(LinearSpring<Friction> l, DampingPolicy d) : law(l), damping(std::move(d)) {}
  void forces(Simulation& s) override {
    if (simd)
      compute_forces_simd(simd, law, s.particles_, s.cell_, s.list_.pairs(), s.list_.index(), s.strain_rate_, s.dt_,
                          *s.pair_forces_, s.sums_);
    else
      compute_forces(law, s.particles_, s.cell_, s.list_.pairs(), s.list_.index(), s.strain_rate_, s.dt_,
                     *s.pair_forces_, s.sums_);
  }
  MotionSums integrate(Simulation& s) override {
    if constexpr (std::is_same_v<DampingPolicy, ViscousDamping>)
      if (simd)
        return integrate_simd<Friction::has_tangential>(damping, s.particles_, s.cell_, s.list_.index(),
                                                        *s.pair_forces_, s.force_, s.dt_);
    return dem::integrate<Friction::has_tangential>(damping, s.particles_, s.cell_, s.list_.index(), *s.pair_forces_,
                                                    s.force_, s.dt_);
  }
};

namespace {
template <class Friction>
std::unique_ptr<Simulation::Kernel> make_kernel(LinearSpring<Friction> law, const Particles& p, const Damping& d,
                                                double dt) {
  if (d.form == Damping::Form::Local)
    return std::make_unique<KernelImpl<Friction, LocalDamping>>(law, LocalDamping(p, d, law.kn, dt));
  return std::make_unique<KernelImpl<Friction, ViscousDamping>>(law, ViscousDamping(p, d, law.kn, dt));
}
}  // namespace

Simulation::Simulation(Particles particles, PeriodicCell cell, Material material, Damping damping, double time_step_s,
                       double verlet_skin_m)
    : particles_(std::move(particles)),
      cell_(cell),
      material_(material),
      damping_(damping),
      dt_(time_step_s),
      list_(verlet_skin_m, material.friction > 0),
      pair_forces_(std::make_unique<PairForces>()) {
  if (material_.friction > 0)
    kernel_ = make_kernel(LinearSpring<Coulomb>{material_.kn_N_per_m, Coulomb{material_.ks_N_per_m, material_.friction}},
                          particles_, damping_, dt_);
  else
    kernel_ = make_kernel(LinearSpring<NoFriction>{material_.kn_N_per_m, {}}, particles_, damping_, dt_);
}

Simulation::~Simulation() = default;
Simulation::Simulation(Simulation&&) noexcept = default;
Simulation& Simulation::operator=(Simulation&&) noexcept = default;

void Simulation::restore(std::int64_t step, const Vec3& strain_rate, PairList contacts) {
  step_ = step;
  strain_rate_ = strain_rate;
  list_.restore(std::move(contacts));
}

void Simulation::restore_checkpoint(std::int64_t step, const Vec3& strain_rate, VerletList::Saved list,
                                    const EnergyBalance& energy) {
  step_ = step;
  strain_rate_ = strain_rate;
  list_.restore_exact(std::move(list), particles_);
  energy_ = energy;
}

void Simulation::step(const CellTargets& targets, const ServoSettings& servo) {
  advance([&] { return servo_strain_rates(targets, sums_.stress_Pa, sums_.stiffness_Pa, servo, dt_); });
}

void Simulation::step(const CellTargets& targets, AdaptiveServo& servo) {
  advance([&] { return servo.rates(targets, sums_.stress_Pa, sums_.stiffness_Pa, dt_); });
}

void Simulation::advance(const std::function<Vec3()>& strain_rates) {
  if (list_.rebuild_due(particles_, cell_)) list_.build(particles_, cell_);
  kernel_->forces(*this);
  if (!sums_.stress_Pa.allFinite()) {
    std::ostringstream msg;
    msg << "non-finite contact stress at step " << step_ << " (time " << time() << " s)";
    throw NonFiniteError(msg.str());
  }
  // The cell's work over the last step, trapezoidal in V sigma (the rate is the one applied since
  // the previous evaluation).
  const Vec3 virial = sums_.stress_Pa.diagonal() * cell_.volume();
  if (energy_.started) energy_.work_by_cell += 0.5 * dt_ * strain_rate_.dot(virial + energy_.virial);
  energy_.virial = virial;
  energy_.elastic = sums_.elastic_normal_J + sums_.elastic_tangential_J;
  energy_.dissipated_friction += sums_.friction_loss_J;
  strain_rate_ = strain_rates();
  const MotionSums motion = kernel_->integrate(*this);
  list_.add_motion(dt_ * std::sqrt(motion.max_speed2));
  kinetic_energy_ = motion.kinetic_half_step;
  energy_.kinetic = motion.kinetic_centred;
  energy_.dissipated_damping += motion.damping_loss;
  if (!energy_.started) energy_.stored_at_start = energy_.stored(), energy_.started = true;
  if (!std::isfinite(kinetic_energy_)) {
    std::ostringstream msg;
    msg << "non-finite kinetic energy or a particle moving more than a cell in one step at step " << step_ << " (time "
        << time() << " s): the run is unstable (time step too large for the stiffness?)";
    throw NonFiniteError(msg.str());
  }
  cell_.deform(strain_rate_, dt_);
  ++step_;
}

}  // namespace dem
