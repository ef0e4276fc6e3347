#include "bench/fused_sweep.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>

#include "dynamics/kernel.hpp"

namespace dem::bench {

struct StepLoops::Impl {
  virtual ~Impl() = default;
  virtual void two_passes() = 0;
  virtual void fused() = 0;
  Particles p;
  PeriodicCell cell;
  VerletList list;
  double dt = 0;
  std::vector<Vec3> net;
  Impl(Particles particles, PeriodicCell c, double skin, bool history, double dt_)
      : p(std::move(particles)), cell(c), list(skin, history), dt(dt_) {}
};

namespace {

template <class Friction>
struct Loops final : StepLoops::Impl {
  static constexpr bool rotate = Friction::has_tangential;
  LinearSpring<Friction> law;
  ViscousDamping damping;
  PairForces pf;
  StepSums sums;
  std::vector<Vec3> torque;                        // per-particle torque sums of the fused sweep
  std::vector<Vec3> scratch_f, scratch_ti, scratch_tj;  // one particle's pairs

  Loops(SavedState st, LinearSpring<Friction> l, const Damping& d, double dt_, double skin)
      : Impl(std::move(st.particles), st.cell, skin, Friction::has_tangential, dt_),
        law(l),
        damping(p, d, l.kn, dt_) {
    if (!rotate) st.contacts.spring.clear(), st.contacts.sliding.clear();
    list.restore(std::move(st.contacts));
  }

  void rebuild_if_due() {
    if (list.rebuild_due(p, cell)) list.build(p, cell);
  }

  void two_passes() override {
    rebuild_if_due();
    compute_forces(law, p, cell, list.pairs(), list.index(), Vec3::Zero(), dt, pf, sums);
    const MotionSums m = integrate<rotate>(damping, p, cell, list.index(), pf, net, dt);
    list.add_motion(dt * std::sqrt(m.max_speed2));
  }

  void fused() override {
    rebuild_if_due();
    PairList& pairs = list.pairs();
    const PairIndex& index = list.index();
    const std::size_t n = p.size();
    // Sized (never touched but for their last entry) by the loops' constructors; the sweep writes
    // pair results into the scratch buffers instead.
    net.assign(n, Vec3::Zero());  // per-particle force sums (then the net forces)
    if (rotate) torque.assign(n, Vec3::Zero());
    PairLoop<Friction> pair_loop(law, p, cell, pairs, Vec3::Zero(), dt, pf);
    const ParticleLoop<rotate, ViscousDamping> particle_loop(damping, p, cell, index, pf, net, dt);
    std::vector<StepSums>& pair_sums = pf.chunk_sums;
    std::vector<MotionSums>& motion_sums = pf.motion_sums;
    for (std::size_t c = 0; c < static_cast<std::size_t>(chunk_count(n)); ++c) {
      StepSums chunk_pairs;
      MotionSums chunk_motion;
      const std::size_t end = std::min(n, (c + 1) * static_cast<std::size_t>(chunk_size));
      for (std::size_t i = c * static_cast<std::size_t>(chunk_size); i < end; ++i) {
        const std::size_t k0 = index.first_begin[i], k1 = index.first_begin[i + 1];
        if (scratch_f.size() < k1 - k0) scratch_f.resize(k1 - k0), scratch_ti.resize(k1 - k0), scratch_tj.resize(k1 - k0);
        // pair(k) writes entry k of the arrays it points at: point them so that entries k0..k1-1
        // land in the scratch buffers (pointers outside an array's bounds before the first write:
        // an experiment's shortcut, kept out of the engine).
        pair_loop.pair_force = scratch_f.data() - k0;
        pair_loop.torque_i = scratch_ti.data() - k0;
        pair_loop.torque_j = scratch_tj.data() - k0;
        Vec3 f = net[i], t = rotate ? torque[i] : Vec3::Zero();  // the pairs where i is second, in pair order
        for (std::size_t k = k0; k < k1; ++k) {
          pair_loop.pair(k, chunk_pairs);
          const std::uint32_t j = pairs.second[k];
          f -= scratch_f[k - k0];
          net[j] += scratch_f[k - k0];
          if constexpr (rotate) {
            t -= scratch_ti[k - k0];
            torque[j] -= scratch_tj[k - k0];
          }
        }
        particle_loop.update(i, f, t, chunk_motion);  // stores f in net[i]
      }
      pair_sums[c] = chunk_pairs;
      motion_sums[c] = chunk_motion;
    }
    sums = total_of_chunks(pair_sums, cell);
    const MotionSums m = total_of_chunks(motion_sums, true);
    list.add_motion(dt * std::sqrt(m.max_speed2));
  }
};

}  // namespace

StepLoops::StepLoops(SavedState state, const Material& material, const Damping& damping, double time_step_s,
                     double skin_m) {
  if (material.friction > 0)
    impl_ = std::make_unique<Loops<Coulomb>>(
        std::move(state), LinearSpring<Coulomb>{material.kn_N_per_m, Coulomb{material.ks_N_per_m, material.friction}},
        damping, time_step_s, skin_m);
  else
    impl_ = std::make_unique<Loops<NoFriction>>(std::move(state), LinearSpring<NoFriction>{material.kn_N_per_m, {}},
                                                damping, time_step_s, skin_m);
}

StepLoops::~StepLoops() = default;
StepLoops::StepLoops(StepLoops&&) noexcept = default;

void StepLoops::step_two_passes() { impl_->two_passes(); }
void StepLoops::step_fused() { impl_->fused(); }
const Particles& StepLoops::particles() const { return impl_->p; }
const std::vector<Vec3>& StepLoops::net_force() const { return impl_->net; }

}  // namespace dem::bench
