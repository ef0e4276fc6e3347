#include "bench/tiling.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <tuple>

namespace dem::bench {

namespace {

// Appends contact (a, b) with its history, oriented so that first < second: the tangential
// history (a spring or a force) is that of `second` relative to `first`, so it changes sign when
// the two swap; the rolling spring, R* (omega_i - omega_j) x n integrated, does not.
void add_contact(PairList& out, ContactHistory& out_history, std::uint32_t a, std::uint32_t b,
                 const ContactHistory& in_history, std::size_t k) {
  const bool swap = b < a;
  out.first.push_back(swap ? b : a);
  out.second.push_back(swap ? a : b);
  if (in_history.has_tangential()) {
    out_history.tangential.push_back(swap ? Vec3(-in_history.tangential[k]) : in_history.tangential[k]);
    out_history.sliding.push_back(in_history.sliding[k]);
  }
  if (in_history.rolling_on) out_history.rolling.push_back(in_history.rolling[k]);
}

// Sorts the contacts by (first, second), carrying their history along.
void sort_contacts(PairList& c, ContactHistory& h) {
  std::vector<std::size_t> order(c.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) {
    return std::tie(c.first[x], c.second[x]) < std::tie(c.first[y], c.second[y]);
  });
  PairList sorted;
  sorted.first.reserve(c.size());
  sorted.second.reserve(c.size());
  for (std::size_t k : order) {
    sorted.first.push_back(c.first[k]);
    sorted.second.push_back(c.second[k]);
  }
  c = std::move(sorted);
  h = h.subset(order);
}

// Bits of x spread to every third bit (x < 2^21): the Morton code's interleaving.
std::uint64_t spread3(std::uint64_t x) {
  x &= 0x1fffff;
  x = (x | x << 32) & 0x1f00000000ffffULL;
  x = (x | x << 16) & 0x1f0000ff0000ffULL;
  x = (x | x << 8) & 0x100f00f00f00f00fULL;
  x = (x | x << 4) & 0x10c30c30c30c30c3ULL;
  x = (x | x << 2) & 0x1249249249249249ULL;
  return x;
}

}  // namespace

SavedState tile(const SavedState& in, int n) {
  if (n < 1) throw std::invalid_argument("tile: n must be at least 1, got " + std::to_string(n));
  const std::size_t count = in.particles.size();
  const std::size_t tiles = static_cast<std::size_t>(n) * static_cast<std::size_t>(n) * static_cast<std::size_t>(n);
  if (count * tiles > std::numeric_limits<std::uint32_t>::max())
    throw std::invalid_argument("tile: " + std::to_string(count * tiles) + " particles do not fit 32-bit indices");
  if (n == 1) return in;
  SavedState out;
  out.cell = PeriodicCell(in.cell.lengths() * n);
  out.cell.set_reference_lengths(in.cell.reference_lengths() * n);
  out.cell.set_tilts(in.cell.tilts() * n);
  out.cell.set_shear_strain(in.cell.shear_strain());
  out.rates = in.rates;
  out.step = in.step;
  out.time_step_s = in.time_step_s;
  const Particles& p = in.particles;
  Particles& q = out.particles;
  for (auto* v : {&q.s, &q.v, &q.omega}) v->reserve(count * tiles);
  for (auto* v : {&q.radius, &q.mass, &q.inertia}) v->reserve(count * tiles);
  const double inv_n = 1.0 / n;
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b)
      for (int c = 0; c < n; ++c)
        for (std::size_t i = 0; i < count; ++i) {
          Vec3 s = (p.s[i] + Vec3(a, b, c)) * inv_n;
          PeriodicCell::wrap_any(s);  // (s + n - 1) / n can round up to 1, which is 0 in a periodic cell
          q.s.push_back(s);
          q.v.push_back(p.v[i]);
          q.omega.push_back(p.omega[i]);
          q.radius.push_back(p.radius[i]);
          q.mass.push_back(p.mass[i]);
          q.inertia.push_back(p.inertia[i]);
        }
  const PairList& c = in.contacts;
  PairList& d = out.contacts;
  out.history = ContactHistory{in.history.tangential_name, in.history.rolling_on, {}, {}, {}};
  d.first.reserve(c.size() * tiles);
  d.second.reserve(c.size() * tiles);
  if (in.history.has_tangential())
    out.history.tangential.reserve(c.size() * tiles), out.history.sliding.reserve(c.size() * tiles);
  const auto tile_index = [n](int a, int b, int c2) {
    const auto wrap = [n](int x) { return ((x % n) + n) % n; };
    return static_cast<std::size_t>((wrap(a) * n + wrap(b)) * n + wrap(c2));
  };
  for (std::size_t k = 0; k < c.size(); ++k) {
    const std::uint32_t i = c.first[k], j = c.second[k];
    // The image of j nearest to i lies `shift` cells away: its copy next to i's copy in tile t
    // is in tile t - shift.
    const Vec3 ds = p.s[j] - p.s[i];
    const Vec3 shift = ds - PeriodicCell::min_image(ds);  // whole numbers, -1, 0 or 1
    const int sa = static_cast<int>(shift[0]), sb = static_cast<int>(shift[1]), sc = static_cast<int>(shift[2]);
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b)
        for (int c2 = 0; c2 < n; ++c2) {
          const auto copy_i = static_cast<std::uint32_t>(tile_index(a, b, c2) * count + i);
          const auto copy_j = static_cast<std::uint32_t>(tile_index(a - sa, b - sb, c2 - sc) * count + j);
          add_contact(d, out.history, copy_i, copy_j, in.history, k);
        }
  }
  sort_contacts(d, out.history);
  return out;
}

SavedState reordered(const SavedState& in, const std::vector<std::uint32_t>& order) {
  const std::size_t count = in.particles.size();
  if (order.size() != count) throw std::invalid_argument("reordered: the order does not have one entry per particle");
  std::vector<std::uint32_t> new_index(count, std::numeric_limits<std::uint32_t>::max());
  for (std::size_t k = 0; k < count; ++k) {
    if (order[k] >= count || new_index[order[k]] != std::numeric_limits<std::uint32_t>::max())
      throw std::invalid_argument("reordered: the order is not a permutation");
    new_index[order[k]] = static_cast<std::uint32_t>(k);
  }
  SavedState out = in;
  const Particles& p = in.particles;
  Particles& q = out.particles;
  for (std::size_t k = 0; k < count; ++k) {
    const std::uint32_t i = order[k];
    q.s[k] = p.s[i], q.v[k] = p.v[i], q.omega[k] = p.omega[i];
    q.radius[k] = p.radius[i], q.mass[k] = p.mass[i], q.inertia[k] = p.inertia[i];
  }
  out.contacts = PairList{};
  out.history = ContactHistory{in.history.tangential_name, in.history.rolling_on, {}, {}, {}};
  for (std::size_t k = 0; k < in.contacts.size(); ++k)
    add_contact(out.contacts, out.history, new_index[in.contacts.first[k]], new_index[in.contacts.second[k]], in.history, k);
  sort_contacts(out.contacts, out.history);
  return out;
}

std::vector<std::uint32_t> spatial_order(const Particles& p, const PeriodicCell& cell) {
  double mean_diameter = 0;
  for (double r : p.radius) mean_diameter += 2 * r;
  mean_diameter /= static_cast<double>(std::max<std::size_t>(1, p.size()));
  int bins[3];
  for (int k = 0; k < 3; ++k)
    bins[k] = std::clamp(static_cast<int>(cell.lengths()[k] / std::max(mean_diameter, 1e-300)), 1, 1 << 21);
  std::vector<std::uint64_t> key(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    std::uint64_t code = 0;
    for (int k = 0; k < 3; ++k) {
      const auto b = static_cast<std::uint64_t>(std::min(bins[k] - 1, static_cast<int>(p.s[i][k] * bins[k])));
      code |= spread3(b) << k;
    }
    key[i] = code;
  }
  std::vector<std::uint32_t> order(p.size());
  std::iota(order.begin(), order.end(), 0U);
  std::stable_sort(order.begin(), order.end(), [&](std::uint32_t x, std::uint32_t y) { return key[x] < key[y]; });
  return order;
}

}  // namespace dem::bench
