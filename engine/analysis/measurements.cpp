#include "analysis/measurements.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <type_traits>
#include <variant>
#include <vector>

#include "contact/scalar_lanes.hpp"

namespace dem {

double void_ratio(const Particles& p, const PeriodicCell& cell) {
  const double vs = total_solid_volume(p);
  return (cell.volume() - vs) / vs;
}

double coordination_number(std::size_t contacts, std::size_t particles) {
  return particles ? 2.0 * static_cast<double>(contacts) / static_cast<double>(particles) : 0.0;
}

namespace {

template <class Law>
ContactCounts count_with(const Law& law, const Simulation& sim, const PairList& pairs, const ContactHistory& history,
                         bool keep_normals, bool keep_network) {
  using O = scalar_lanes::Ops;
  const Particles& p = sim.particles();
  std::vector<unsigned> per_particle(p.size(), 0);
  ContactCounts c;
  double sum_fn = 0;
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const auto i = pairs.first[k], j = pairs.second[k];
    const double rsum = p.radius[i] + p.radius[j];
    const Vec3 l = sim.cell().branch(p.s[i], p.s[j]);
    const double dist2 = l.squaredNorm();
    if (dist2 >= rsum * rsum) continue;
    const double dist = std::sqrt(dist2);
    const double overlap = rsum - dist;
    const double reduced_radius = Law::needs_reduced_radius ? (p.radius[i] * p.radius[j]) / rsum : 0.0;
    const double fn = law.normal.template force<O>(overlap, reduced_radius);
    c.elastic_normal_J += law.normal.template energy<O>(fn, overlap);
    Vec3 f = fn / dist * l;
    double ft_norm = 0;
    if constexpr (Law::has_tangential) {
      const auto ft = law.tangential.template force_of<O>(scalar_lanes::lanes_of(history.tangential[k]), overlap, reduced_radius);
      c.elastic_tangential_J += law.tangential.template energy<O>(ft, overlap, reduced_radius);
      const Vec3 tangential = scalar_lanes::vec3_of(ft);
      f += tangential;
      ft_norm = tangential.norm();
      if (history.sliding[k]) ++c.sliding;
    }
    if constexpr (Law::has_rolling) c.elastic_rolling_J += law.rolling.template opening_loss<O>(history.rolling[k].squaredNorm());
    if (keep_network) {
      c.pairs.push_back(i), c.pairs.push_back(j);
      c.tangential_forces_N.push_back(ft_norm);
      c.branches.push_back(l);
    }
    c.stress_Pa += f * l.transpose();
    sum_fn += fn;
    if (keep_normals) c.normals.push_back(l / dist);
    if (keep_normals || keep_network) c.normal_forces_N.push_back(fn);
    ++c.contacts;
    ++per_particle[i];
    ++per_particle[j];
  }
  const Mat3 sum = c.stress_Pa;  // a copy: assigning (A + A^T) to A itself aliases in Eigen
  c.stress_Pa = 0.5 * (sum + sum.transpose()) / sim.cell().volume();
  c.mean_normal_force_N = c.contacts ? sum_fn / static_cast<double>(c.contacts) : 0.0;
  for (unsigned n : per_particle) {
    if (n == 0) ++c.particles_no_contact;
    if (n == 1) ++c.particles_one_contact;
  }
  return c;
}

}  // namespace

ContactCounts count_contacts(const Simulation& sim, bool keep_normals, bool keep_network) {
  // A simulation built from particles (a lattice, a CSV file) has no neighbour list until its
  // first step builds one, yet its particles may already overlap (a packing read from a CSV file):
  // its first row reported no contacts and zero stress. It is measured over a list built here from
  // the same positions, with unloaded histories, which is what its own histories are before its
  // first step. (A simulation restored from a saved state has the saved contacts as its list.)
  if (sim.verlet_list().builds() == 0 && sim.pairs().size() == 0) {
    VerletList list(sim.verlet_list().skin());
    list.build(sim.particles(), sim.cell());
    ContactHistory unloaded = sim.history();
    unloaded.reset(list.pairs().size());
    return std::visit([&](const auto& law) { return count_with(law, sim, list.pairs(), unloaded, keep_normals, keep_network); },
                      sim.material().law);
  }
  return std::visit([&](const auto& law) { return count_with(law, sim, sim.pairs(), sim.history(), keep_normals, keep_network); },
                    sim.material().law);
}

double mechanical_coordination_number(const ContactCounts& c, std::size_t particles) {
  const double n = static_cast<double>(particles - c.particles_no_contact - c.particles_one_contact);
  return n > 0 ? (2.0 * static_cast<double>(c.contacts) - static_cast<double>(c.particles_one_contact)) / n : 0.0;
}

double unbalanced_force_ratio(const Simulation& sim) {
  const StepSums& s = sim.sums();
  if (s.contacts == 0 || s.sum_normal_force_N <= 0) return 1.0;
  double sum_net = 0;
  for (const Vec3& f : sim.net_force()) sum_net += f.norm();
  const double mean_net = sum_net / static_cast<double>(sim.net_force().size());
  return mean_net / (s.sum_normal_force_N / static_cast<double>(s.contacts));
}

namespace {
// Calls f(law, i, j, overlap, reduced radius) for each pair in contact at the current positions.
template <class F>
void for_each_contact(const Simulation& sim, F&& f) {
  std::visit(
      [&](const auto& law) {
        const Particles& p = sim.particles();
        const PairList& pairs = sim.pairs();
        for (std::size_t k = 0; k < pairs.size(); ++k) {
          const auto i = pairs.first[k], j = pairs.second[k];
          const double rsum = p.radius[i] + p.radius[j];
          const double dist = sim.cell().branch(p.s[i], p.s[j]).norm();
          if (!(dist < rsum)) continue;
          f(law, i, j, rsum - dist, (p.radius[i] * p.radius[j]) / rsum);
        }
      },
      sim.material().law);
}

// The factor the contact dashpots put on the critical step (1 without them).
double dashpot_factor(const AnyContactLaw& law) {
  return std::visit(
      [](const auto& l) {
        if constexpr (std::decay_t<decltype(l)>::damped) return l.normal.damped_factor();
        return 1.0;
      },
      law);
}
}  // namespace

double dashpot_step_number(const Simulation& sim) {
  using O = scalar_lanes::Ops;
  const Particles& p = sim.particles();
  std::vector<double> sum(p.size(), 0.0);  // sum_c max(c_n, c_t) per particle [kg/s]
  bool damped = false;
  for_each_contact(sim, [&](const auto& law, auto i, auto j, double overlap, double reduced_radius) {
    using Law = std::decay_t<decltype(law)>;
    if constexpr (Law::damped) {
      damped = true;
      const double m_star = (p.mass[i] * p.mass[j]) / (p.mass[i] + p.mass[j]);
      double k_max = law.normal.template stiffness<O>(overlap, reduced_radius);
      if constexpr (Law::has_tangential) k_max = std::max(k_max, law.tangential.template stiffness<O>(overlap, reduced_radius));
      const double c = 2 * law.normal.damping_ratio * std::sqrt(m_star * k_max);
      sum[i] += c, sum[j] += c;
    }
  });
  if (!damped) return 0.0;
  double largest = 0;
  for (std::size_t i = 0; i < p.size(); ++i) largest = std::max(largest, sum[i] / p.mass[i]);
  return sim.time_step() * largest;
}

double time_step_over_critical(const Simulation& sim) {
  return sim.time_step() / critical_time_step(sim.material().law, sim.particles(), sim.material().density_kg_per_m3);
}

double time_step_over_contact_critical(const Simulation& sim) {
  using O = scalar_lanes::Ops;
  double k_max = 0;
  for_each_contact(sim, [&](const auto& law, auto, auto, double overlap, double reduced_radius) {
    k_max = std::max(k_max, law.normal.template stiffness<O>(overlap, reduced_radius));
  });
  if (!(k_max > 0)) return 0.0;
  const Particles& p = sim.particles();
  const double m_min = *std::min_element(p.mass.begin(), p.mass.end());
  return sim.time_step() / (2 * std::sqrt(m_min / k_max) * dashpot_factor(sim.material().law));
}

double translational_kinetic_energy(const Particles& p) {
  double e = 0;
  for (std::size_t i = 0; i < p.size(); ++i) e += 0.5 * p.mass[i] * p.v[i].squaredNorm();
  return e;
}

double rotational_kinetic_energy(const Particles& p) {
  double e = 0;
  for (std::size_t i = 0; i < p.size(); ++i) e += 0.5 * p.inertia[i] * p.omega[i].squaredNorm();
  return e;
}

double mean_stress(const Mat3& stress_Pa) { return stress_Pa.trace() / 3.0; }

double deviator_stress(const Mat3& stress_Pa) {
  const Vec3 s = Eigen::SelfAdjointEigenSolver<Mat3>(stress_Pa, Eigen::EigenvaluesOnly).eigenvalues();
  return std::sqrt(0.5 * ((s[0] - s[1]) * (s[0] - s[1]) + (s[1] - s[2]) * (s[1] - s[2]) + (s[0] - s[2]) * (s[0] - s[2])));
}

double mean_diameter(const Particles& p) {
  double d = 0;
  for (double r : p.radius) d += 2 * r;
  return p.size() ? d / static_cast<double>(p.size()) : 0.0;
}

double max_strain_rate(const CellRates& rates) {
  return std::max(rates.axial.cwiseAbs().maxCoeff(), rates.shear.cwiseAbs().maxCoeff());
}

double inertial_number(const Simulation& sim, double p) {
  if (p <= 0) return 0.0;
  const Particles& parts = sim.particles();
  return max_strain_rate(sim.rates()) * mean_diameter(parts) * std::sqrt(sim.material().density_kg_per_m3 / p);
}

}  // namespace dem
