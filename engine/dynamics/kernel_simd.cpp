#include "dynamics/kernel_simd.hpp"

#include <immintrin.h>

#include <bit>
#include <cstdlib>
#include <string_view>

// Only the functions marked AVX2 use AVX2 (a function attribute, not a compiler flag), so the rest
// of the engine, Eigen included, is compiled exactly as before and runs on any x86-64. AVX2
// without FMA: the compiler cannot fuse a multiply and an add, which would change the rounding.
#define AVX2 __attribute__((target("avx2")))

namespace dem {

bool simd_forces_available() {
  static const bool available = __builtin_cpu_supports("avx2");
  return available;
}

namespace {
bool& simd_switch() {
  static bool on = [] {
    const char* env = std::getenv("DEM_SIMD");
    return !(env && std::string_view(env) == "0");
  }();
  return on;
}
}  // namespace

bool simd_forces_enabled() { return simd_forces_available() && simd_switch(); }
void enable_simd_forces(bool on) { simd_switch() = on; }

namespace {

using V = __m256d;  // four lanes: four consecutive pairs

struct V3 {
  V x, y, z;
};

AVX2 inline V splat(double a) { return _mm256_set1_pd(a); }
AVX2 inline V zero() { return _mm256_setzero_pd(); }
AVX2 inline V select(V mask, V if_true, V if_false) { return _mm256_blendv_pd(if_false, if_true, mask); }
AVX2 inline V keep(V mask, V a) { return _mm256_and_pd(mask, a); }  // a where mask, else +0.0
AVX2 inline V3 keep(V mask, const V3& a) { return {keep(mask, a.x), keep(mask, a.y), keep(mask, a.z)}; }
AVX2 inline V3 select(V mask, const V3& t, const V3& f) {
  return {select(mask, t.x, f.x), select(mask, t.y, f.y), select(mask, t.z, f.z)};
}

// Eigen's order for 3-vectors: (x + y) + z, and the cross product's differences of products.
AVX2 inline V dot(const V3& a, const V3& b) { return (a.x * b.x + a.y * b.y) + a.z * b.z; }
AVX2 inline V3 operator+(const V3& a, const V3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
AVX2 inline V3 operator-(const V3& a, const V3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
AVX2 inline V3 operator*(V s, const V3& a) { return {s * a.x, s * a.y, s * a.z}; }
AVX2 inline V3 cross(const V3& a, const V3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

// Four consecutive Vec3 (12 doubles, x0 y0 z0 x1 | y1 z1 x2 y2 | z2 x3 y3 z3) to and from lanes.
AVX2 inline V3 load4(const Vec3* p) {
  const double* d = p->data();
  const V in0 = _mm256_loadu_pd(d), in1 = _mm256_loadu_pd(d + 4), in2 = _mm256_loadu_pd(d + 8);
  const V a = _mm256_permute2f128_pd(in0, in1, 0x30);  // x0 y0 | x2 y2
  const V c = _mm256_permute2f128_pd(in0, in2, 0x21);  // z0 x1 | z2 x3
  const V b = _mm256_permute2f128_pd(in1, in2, 0x30);  // y1 z1 | y3 z3
  return {_mm256_shuffle_pd(a, c, 0xA), _mm256_shuffle_pd(a, b, 0x5), _mm256_shuffle_pd(c, b, 0xA)};
}
AVX2 inline void store4(Vec3* p, const V3& v) {
  double* d = p->data();
  const V a = _mm256_unpacklo_pd(v.x, v.y);         // x0 y0 | x2 y2
  const V c = _mm256_shuffle_pd(v.z, v.x, 0xA);     // z0 x1 | z2 x3
  const V b = _mm256_unpackhi_pd(v.y, v.z);         // y1 z1 | y3 z3
  _mm256_storeu_pd(d, _mm256_permute2f128_pd(a, c, 0x20));
  _mm256_storeu_pd(d + 4, _mm256_permute2f128_pd(b, a, 0x30));
  _mm256_storeu_pd(d + 8, _mm256_permute2f128_pd(c, b, 0x31));
}
// PeriodicCell::branch, one axis: the nearest image of b - a (fractional) times the cell length.
AVX2 inline V branch(V a, V b, V length) {
  const V magic = splat(6755399441055744.0);  // 1.5 * 2^52, see PeriodicCell::min_image
  const V ds = b - a;
  return (ds - ((ds + magic) - magic)) * length;
}
// base[index[p]] for the four lanes p (the masked form: the plain one trips GCC 12's
// -Wmaybe-uninitialized inside its own header).
AVX2 inline V gather(const double* base, __m128i index) {
  return _mm256_mask_i32gather_pd(zero(), base, index, _mm256_castsi256_pd(_mm256_set1_epi64x(-1)), 8);
}
// Particle vectors of four pairs; `index3` holds 3 x the particle indices (doubles per Vec3).
AVX2 inline V3 gather(const Vec3* base, __m128i index3) {
  const double* d = base->data();
  return {gather(d, index3), gather(d + 1, index3), gather(d + 2, index3)};
}

// The 16 chunk sums as four vectors, component c in acc[c / 4], lane c % 4: the stress
// column-major (f_a l_b at a + 3 b), the servo stiffness, then sum fn, normal and tangential
// elastic energy, friction loss. Each pair's 16 values are added in pair order.
struct Accumulator {
  V acc[4];
  std::size_t contacts = 0;

  AVX2 explicit Accumulator(const StepSums& s) {
    const Mat3& m = s.stress_Pa;
    const Vec3& k = s.stiffness_Pa;
    acc[0] = _mm256_setr_pd(m(0, 0), m(1, 0), m(2, 0), m(0, 1));
    acc[1] = _mm256_setr_pd(m(1, 1), m(2, 1), m(0, 2), m(1, 2));
    acc[2] = _mm256_setr_pd(m(2, 2), k[0], k[1], k[2]);
    acc[3] = _mm256_setr_pd(s.sum_normal_force_N, s.elastic_normal_J, s.elastic_tangential_J, s.friction_loss_J);
    contacts = s.contacts;
  }
  AVX2 StepSums sums() const {
    alignas(32) double a[16];
    for (int g = 0; g < 4; ++g) _mm256_store_pd(a + 4 * g, acc[g]);
    StepSums s;
    for (int c = 0; c < 9; ++c) s.stress_Pa(c % 3, c / 3) = a[c];
    s.stiffness_Pa = Vec3(a[9], a[10], a[11]);
    s.sum_normal_force_N = a[12];
    s.elastic_normal_J = a[13];
    s.elastic_tangential_J = a[14];
    s.friction_loss_J = a[15];
    s.contacts = contacts;
    return s;
  }
  // Adds four pairs' values, given per component (comp[c] holds the four pairs' values of
  // component c), pair by pair. `groups` = 1 adds only the last group (the others are zero).
  AVX2 void add(const V (&comp)[16], int first_group = 0) {
    for (int g = first_group; g < 4; ++g) {  // transpose 4 x 4: row[p] = pair p's 4 components of group g
      const V t0 = _mm256_unpacklo_pd(comp[4 * g], comp[4 * g + 1]);
      const V t1 = _mm256_unpackhi_pd(comp[4 * g], comp[4 * g + 1]);
      const V t2 = _mm256_unpacklo_pd(comp[4 * g + 2], comp[4 * g + 3]);
      const V t3 = _mm256_unpackhi_pd(comp[4 * g + 2], comp[4 * g + 3]);
      const V row0 = _mm256_permute2f128_pd(t0, t2, 0x20), row1 = _mm256_permute2f128_pd(t1, t3, 0x20);
      const V row2 = _mm256_permute2f128_pd(t0, t2, 0x31), row3 = _mm256_permute2f128_pd(t1, t3, 0x31);
      acc[g] = (((acc[g] + row0) + row1) + row2) + row3;
    }
  }
};

template <class Friction>
AVX2 void chunk(const PairLoop<Friction>& loop, std::size_t begin, std::size_t end, StepSums& out) {
  constexpr bool frictional = Friction::has_tangential;
  Accumulator acc{StepSums{}};
  const Vec3& L = loop.cell.lengths();
  const V Lx = splat(L[0]), Ly = splat(L[1]), Lz = splat(L[2]);
  const V kn = splat(loop.law.kn), half = splat(0.5);
  const Vec3& rate = loop.strain_rate;
  const V rate_x = splat(rate[0]), rate_y = splat(rate[1]), rate_z = splat(rate[2]);
  double ks_ = 0, mu_ = 0;
  if constexpr (frictional) ks_ = loop.law.friction.ks, mu_ = loop.law.friction.mu;
  const V ks = splat(ks_), minus_ks = splat(-ks_), ks2 = splat(ks_ * ks_), half_ks = splat(0.5 * ks_), mu = splat(mu_);
  const V dt = splat(loop.dt);
  std::size_t k = begin;
  for (; k + 4 <= end; k += 4) {
    const __m128i ii = _mm_loadu_si128(reinterpret_cast<const __m128i*>(loop.first + k));
    const __m128i jj = _mm_loadu_si128(reinterpret_cast<const __m128i*>(loop.second + k));
    const __m128i ii3 = _mm_add_epi32(ii, _mm_add_epi32(ii, ii)), jj3 = _mm_add_epi32(jj, _mm_add_epi32(jj, jj));
    const V3 si = gather(loop.s, ii3), sj = gather(loop.s, jj3);
    const V3 l{branch(si.x, sj.x, Lx), branch(si.y, sj.y, Ly), branch(si.z, sj.z, Lz)};
    const V dist2 = dot(l, l);
    const V ri = gather(loop.radius, ii), rj = gather(loop.radius, jj);
    const V rsum = ri + rj;
    const V touch = _mm256_cmp_pd(dist2, rsum * rsum, _CMP_NGE_UQ);  // !(dist2 >= rsum^2), as the scalar test
    const int touching = _mm256_movemask_pd(touch);
    V comp[16];
    if (touching == 0) {  // no contact in these four pairs
      store4(loop.pair_force + k, V3{zero(), zero(), zero()});
      if constexpr (frictional) {
        store4(loop.torque_i + k, V3{zero(), zero(), zero()});
        store4(loop.torque_j + k, V3{zero(), zero(), zero()});
        const V3 u = load4(loop.spring + k);
        for (int c = 12; c < 15; ++c) comp[c] = zero();
        comp[15] = half_ks * dot(u, u);
        store4(loop.spring + k, V3{zero(), zero(), zero()});
        for (int p = 0; p < 4; ++p) loop.sliding_flag[k + p] = 0;
        acc.add(comp, 3);
      }
      continue;
    }
    const V dist = _mm256_sqrt_pd(dist2);
    const V3 n{l.x / dist, l.y / dist, l.z / dist};
    const V overlap = rsum - dist;
    const V fn = kn * overlap;
    V3 f = fn * n;
    comp[15] = zero();
    if constexpr (frictional) {
      const V arm_i = ri - half * overlap, arm_j = rj - half * overlap;
      const V3 vi = gather(loop.v, ii3), vj = gather(loop.v, jj3);
      const V3 wi = gather(loop.omega, ii3), wj = gather(loop.omega, jj3);
      const V3 spin = cross(arm_i * wi + arm_j * wj, n);
      const V3 v_rel{((vj.x - vi.x) - rate_x * l.x) - spin.x, ((vj.y - vi.y) - rate_y * l.y) - spin.y,
                     ((vj.z - vi.z) - rate_z * l.z) - spin.z};
      const V3 v_t = v_rel - dot(n, v_rel) * n;
      // Coulomb::tangential, lane by lane.
      V3 u = load4(loop.spring + k);
      const V old2 = dot(u, u);
      const V had_spring = _mm256_cmp_pd(old2, zero(), _CMP_GT_OQ);
      const V3 turned = u - dot(n, u) * n;
      const V new2 = dot(turned, turned);
      const V rescale = _mm256_and_pd(had_spring, _mm256_cmp_pd(new2, zero(), _CMP_GT_OQ));
      u = select(had_spring, select(rescale, _mm256_sqrt_pd(old2 / new2) * turned, turned), u);
      const V3 du = dt * v_t;
      const V3 u_old = u;
      u = u + du;
      const V limit = mu * fn;
      const V sliding = _mm256_cmp_pd(ks2 * dot(u, u), limit * limit, _CMP_GE_OQ);
      const V norm = _mm256_sqrt_pd(dot(u, u));
      const V cap = select(_mm256_cmp_pd(norm, zero(), _CMP_GT_OQ), limit / (ks * norm), zero());
      const V3 capped = cap * u;
      const V lost = half_ks * (dot(u_old + capped, du) - (dot(capped, capped) - dot(u_old, u_old)));
      u = select(sliding, capped, u);
      const V3 ft = minus_ks * u;
      const int slid = _mm256_movemask_pd(_mm256_and_pd(sliding, touch));
      for (int p = 0; p < 4; ++p) loop.sliding_flag[k + p] = static_cast<std::uint8_t>((slid >> p) & 1);
      comp[14] = keep(touch, (half * dot(ft, ft)) / ks);
      comp[15] = select(touch, keep(sliding, lost), half_ks * old2);  // an opening contact loses its spring
      f = f + ft;
      const V3 nxft = cross(n, ft);
      store4(loop.spring + k, keep(touch, u));
      store4(loop.torque_i + k, keep(touch, arm_i * nxft));
      store4(loop.torque_j + k, keep(touch, arm_j * nxft));
    } else {
      comp[14] = zero();
    }
    f = keep(touch, f);
    store4(loop.pair_force + k, f);
    const V lx = keep(touch, l.x), ly = keep(touch, l.y), lz = keep(touch, l.z);
    comp[0] = f.x * lx, comp[1] = f.y * lx, comp[2] = f.z * lx;
    comp[3] = f.x * ly, comp[4] = f.y * ly, comp[5] = f.z * ly;
    comp[6] = f.x * lz, comp[7] = f.y * lz, comp[8] = f.z * lz;
    const V nlx = n.x * l.x, nly = n.y * l.y, nlz = n.z * l.z;
    comp[9] = keep(touch, kn * (nlx * nlx));
    comp[10] = keep(touch, kn * (nly * nly));
    comp[11] = keep(touch, kn * (nlz * nlz));
    comp[12] = keep(touch, fn);
    comp[13] = keep(touch, (half * fn) * overlap);
    acc.add(comp);
    acc.contacts += static_cast<std::size_t>(std::popcount(static_cast<unsigned>(touching)));
  }
  out = acc.sums();
  for (; k < end; ++k) loop.pair(k, out);  // the last pairs of the list, one by one
}

}  // namespace

template <class Friction>
void compute_forces_simd(const LinearSpring<Friction>& law, const Particles& p, const PeriodicCell& cell,
                         PairList& pairs, const Vec3& strain_rate, double dt, PairForces& out, StepSums& sums) {
  const PairLoop<Friction> loop(law, p, cell, pairs, strain_rate, dt, out);
  const std::ptrdiff_t chunks = chunk_count(loop.n_pairs);
  StepSums* chunk_sums = out.chunk_sums.data();
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t c = 0; c < chunks; ++c) {
    const std::size_t begin = static_cast<std::size_t>(c * chunk_size);
    chunk(loop, begin, std::min(loop.n_pairs, begin + static_cast<std::size_t>(chunk_size)), chunk_sums[c]);
  }
  sums = total_of_chunks(out.chunk_sums, cell);
}

template void compute_forces_simd<NoFriction>(const LinearSpring<NoFriction>&, const Particles&, const PeriodicCell&,
                                              PairList&, const Vec3&, double, PairForces&, StepSums&);
template void compute_forces_simd<Coulomb>(const LinearSpring<Coulomb>&, const Particles&, const PeriodicCell&,
                                           PairList&, const Vec3&, double, PairForces&, StepSums&);

}  // namespace dem
