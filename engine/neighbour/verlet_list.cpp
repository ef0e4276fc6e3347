#include "neighbour/verlet_list.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include <Eigen/SVD>

namespace dem {

void PairIndex::build(const PairList& pairs, std::size_t particles) {
  first_begin.assign(particles + 1, 0);
  second_begin.assign(particles + 1, 0);
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    ++first_begin[pairs.first[k] + 1];
    ++second_begin[pairs.second[k] + 1];
  }
  for (std::size_t i = 0; i < particles; ++i) {
    first_begin[i + 1] += first_begin[i];
    second_begin[i + 1] += second_begin[i];
  }
  second_pairs.resize(pairs.size());
  std::vector<std::uint32_t> fill(second_begin.begin(), second_begin.end() - 1);
  for (std::size_t k = 0; k < pairs.size(); ++k) second_pairs[fill[pairs.second[k]]++] = static_cast<std::uint32_t>(k);
}

namespace {
Vec3 singular_values(const Mat3& m) { return Eigen::JacobiSVD<Mat3>(m).singularValues(); }  // descending
}  // namespace

namespace {
// The two largest of a set of values, a >= b (a maximum: the same whatever the order or the number
// of threads).
struct TwoLargest {
  double a = 0, b = 0;
  void add(double x) {
    if (x > a) b = a, a = x;
    else if (x > b) b = x;
  }
  void merge(const TwoLargest& other) { add(other.a), add(other.b); }
};
#pragma omp declare reduction(two_largest : TwoLargest : omp_out.merge(omp_in))
}  // namespace

double VerletList::displacement_closing(const Particles& p, const PeriodicCell& cell) const {
  TwoLargest disp2;  // squared displacements
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(p.size());
#pragma omp parallel for schedule(static) reduction(two_largest : disp2)
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    const Vec3 ds = PeriodicCell::min_image(p.s[i] - s_at_build_[i]);
    disp2.add(cell.to_real(ds).squaredNorm());
  }
  return std::sqrt(disp2.a) + std::sqrt(disp2.b);
}

double VerletList::affine_closing(const PeriodicCell& cell) const {
  // A branch vector l at the build is H H_build^-1 l now: it is at least lambda_min |l| long.
  const double lambda_min = cell.sheared() || cell_at_build_.sheared()
                                ? singular_values(cell.matrix() * cell_at_build_.matrix().inverse())[2]
                                : cell.lengths().cwiseQuotient(cell_at_build_.lengths()).minCoeff();
  return (2 * max_radius_ + skin_) * std::max(0.0, 1.0 - lambda_min);
}

bool VerletList::needs_rebuild(const Particles& p, const PeriodicCell& cell) const {
  if (!built_ || p.size() != s_at_build_.size()) return true;
  return beyond_skin(displacement_closing(p, cell), affine_closing(cell));
}

bool VerletList::rebuild_due(const Particles& p, const PeriodicCell& cell) {
  if (!built_ || p.size() != s_at_build_.size()) return true;
  // A particle's displacement relative to the cell, measured with today's sides, is at most its
  // displacement at the last measurement plus the motion since, times the largest L / L_min; so is
  // d_1 + d_2 with d_1 + d_2 then and twice the motion (drift_m_). The 0.1 % margins cover round-off.
  const Vec3& L = cell.lengths();
  lengths_min_ = lengths_min_.cwiseMin(L);
  double stretch = L.cwiseQuotient(lengths_min_).maxCoeff();
  if (cell.sheared() || smallest_singular_value_ > 0) {  // |H d| <= s_max(H_now) / s_min(H_then) |H_then d|
    const Vec3 sv = singular_values(cell.matrix());
    smallest_singular_value_ = smallest_singular_value_ > 0 ? std::min(smallest_singular_value_, sv[2]) : sv[2];
    stretch = sv[0] / smallest_singular_value_;
  }
  const double affine = affine_closing(cell);
  if (1.001 * stretch * drift_m_ + affine <= 0.999 * skin_) return false;  // false for a NaN bound too
  ++exact_checks_;
  const double closing = displacement_closing(p, cell);
  drift_m_ = closing, lengths_min_ = L;
  smallest_singular_value_ = cell.sheared() ? singular_values(cell.matrix())[2] : 0;
  return beyond_skin(closing, affine);
}

void VerletList::collect_pairs(const Particles& p, const PeriodicCell& cell, PairList& out) const {
  const std::size_t n = p.size();
  // Bins of at least `range` between opposite faces: a ball of that radius spans at most one bin
  // on either side along every fractional axis, whatever the tilt.
  const Vec3 width = cell.widths();
  const double range = 2 * max_radius_ + skin_;
  int nb[3];
  for (int k = 0; k < 3; ++k) nb[k] = static_cast<int>(std::floor(width[k] / range));
  auto within = [&](std::size_t i, std::size_t j) {
    const double cut = p.radius[i] + p.radius[j] + skin_;
    return cell.branch(p.s[i], p.s[j]).squaredNorm() < cut * cut;
  };
  std::vector<std::uint32_t> js;
  if (std::min({nb[0], nb[1], nb[2]}) < 3) {  // too few bins for a 27-bin stencil: all pairs
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j)
        if (within(i, j)) {
          out.first.push_back(static_cast<std::uint32_t>(i));
          out.second.push_back(static_cast<std::uint32_t>(j));
        }
    return;
  }
  // Counting sort of particles into bins (fractional coordinates, so bins deform with the cell).
  const std::size_t nbins = static_cast<std::size_t>(nb[0]) * nb[1] * nb[2];
  auto bin_of = [&](const Vec3& s, int k) { return std::min(nb[k] - 1, static_cast<int>(s[k] * nb[k])); };
  std::vector<std::uint32_t> start(nbins + 1, 0), members(n);
  std::vector<std::uint32_t> bin(n);
  for (std::size_t i = 0; i < n; ++i) {
    bin[i] = static_cast<std::uint32_t>((bin_of(p.s[i], 0) * nb[1] + bin_of(p.s[i], 1)) * nb[2] + bin_of(p.s[i], 2));
    ++start[bin[i] + 1];
  }
  for (std::size_t b = 0; b < nbins; ++b) start[b + 1] += start[b];
  std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
  for (std::size_t i = 0; i < n; ++i) members[fill[bin[i]]++] = static_cast<std::uint32_t>(i);

  for (std::size_t i = 0; i < n; ++i) {
    const int b0 = bin_of(p.s[i], 0), b1 = bin_of(p.s[i], 1), b2 = bin_of(p.s[i], 2);
    js.clear();
    for (int d0 = -1; d0 <= 1; ++d0)
      for (int d1 = -1; d1 <= 1; ++d1)
        for (int d2 = -1; d2 <= 1; ++d2) {
          const int c0 = (b0 + d0 + nb[0]) % nb[0], c1 = (b1 + d1 + nb[1]) % nb[1], c2 = (b2 + d2 + nb[2]) % nb[2];
          const std::size_t c = (static_cast<std::size_t>(c0) * nb[1] + c1) * nb[2] + c2;
          for (std::uint32_t m = start[c]; m < start[c + 1]; ++m) {
            const std::uint32_t j = members[m];
            if (j > i && within(i, j)) js.push_back(j);
          }
        }
    std::sort(js.begin(), js.end());
    for (std::uint32_t j : js) {
      out.first.push_back(static_cast<std::uint32_t>(i));
      out.second.push_back(j);
    }
  }
}

namespace {
double largest_radius(const Particles& p) {
  return p.size() ? *std::max_element(p.radius.begin(), p.radius.end()) : 0.0;
}
}  // namespace

void VerletList::restore_exact(Saved saved, const Particles& p) {
  pairs_ = std::move(saved.pairs);
  ++changes_;
  s_at_build_ = std::move(saved.s_at_build);
  cell_at_build_.set_lengths(saved.lengths_at_build);
  cell_at_build_.set_tilts(saved.tilts_at_build);
  builds_ = saved.builds;
  built_ = true;
  drift_m_ = std::numeric_limits<double>::infinity();  // measured at the next check
  max_radius_ = largest_radius(p);
  index_.build(pairs_, p.size());
}

void VerletList::build(const Particles& p, const PeriodicCell& cell, ContactHistory* history) {
  max_radius_ = largest_radius(p);  // the particles' own: collect_pairs bins by it
  const double range = 2 * max_radius_ + skin_;
  const Vec3 width = cell.widths();
  for (int k = 0; k < 3; ++k) {
    if (width[k] <= 2 * range) {
      std::ostringstream msg;
      msg << (cell.sheared() ? "cell width " : "cell side L") << k + 1 << " = " << width[k]
          << " m is not larger than twice the contact range "
          << "2*(largest diameter + skin) = " << 2 * range << " m: the periodic minimum image would be ambiguous";
      throw std::runtime_error(msg.str());
    }
  }
  // Everything is built aside first: if an allocation fails, the list and the history stay as they were.
  PairList fresh;
  collect_pairs(p, cell, fresh);
  // Where each pair was before (both lists sorted by (i, j)), for the contact history; not needed
  // by a law that keeps none (a frictionless scene).
  const bool carries = !history || history->has_tangential() || history->rolling_on;
  std::vector<std::uint32_t> from_previous(carries ? fresh.size() : 0, ContactHistory::none);
  std::size_t o = 0;
  for (std::size_t k = 0; carries && k < fresh.size() && o < pairs_.size(); ++k) {
    const auto key = std::make_pair(fresh.first[k], fresh.second[k]);
    while (o < pairs_.size() && std::make_pair(pairs_.first[o], pairs_.second[o]) < key) ++o;
    if (o < pairs_.size() && pairs_.first[o] == key.first && pairs_.second[o] == key.second)
      from_previous[k] = static_cast<std::uint32_t>(o);
  }
  PairIndex index;
  index.build(fresh, p.size());
  std::vector<Vec3> s_at_build = p.s;
  ContactHistory carried;
  if (history) carried = history->carried(from_previous);
  // Commit: nothing below throws.
  pairs_ = std::move(fresh);
  ++changes_;
  index_ = std::move(index);
  from_previous_ = std::move(from_previous);
  s_at_build_ = std::move(s_at_build);
  if (history) *history = std::move(carried);
  cell_at_build_ = cell;
  drift_m_ = 0, lengths_min_ = cell.lengths();
  smallest_singular_value_ = cell.sheared() ? singular_values(cell.matrix())[2] : 0;
  built_ = true;
  ++builds_;
}

}  // namespace dem
