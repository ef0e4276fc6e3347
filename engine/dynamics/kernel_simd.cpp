#include "dynamics/kernel_simd.hpp"

#include <immintrin.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cstdio>
#include <cstdlib>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <variant>

#include "contact/scalar_lanes.hpp"

// Each instruction set's loops are compiled for it alone (a `#pragma GCC target` region; for clang
// a `#pragma clang attribute` that gives each function of the region the target), not by a
// compiler flag, so the rest of the engine, Eigen included, is compiled as before and runs on any
// x86-64. The file is compiled with -ffp-contract=off (engine/CMakeLists.txt): AVX-512 implies
// FMA, and a fused multiply-add would round differently from the scalar code.

// The gathers are always inlined in the unit of the laws with contact dashpots, whose pair loop
// GCC otherwise left calling them (4 % of a dashpot run); in the other units GCC inlines them by
// itself, and their code stays as it was.
#if defined(DEM_KERNEL_UNIT) && DEM_KERNEL_UNIT == 1
#define DEM_GATHER_INLINE [[gnu::always_inline]]
#else
#define DEM_GATHER_INLINE
#endif

namespace dem {

#ifndef DEM_KERNEL_UNIT  // the first unit: what is compiled once
int simd_width_available() {
  static const int width = __builtin_cpu_supports("avx512f") ? 8 : __builtin_cpu_supports("avx2") ? 4 : 0;
  return width;
}

namespace {
int& simd_cap() {
  static int cap = [] {
    const char* env = std::getenv("DEM_SIMD");
    const std::string_view v = env ? env : "8";
    if (v == "0" || v == "4" || v == "8") return v[0] - '0';
    std::fprintf(stderr, "DEM_SIMD=%s ignored: 0 (scalar loops), 4 (at most AVX2) or 8 (at most AVX-512)\n", env);
    return 8;
  }();
  return cap;
}
}  // namespace

int simd_width() { return std::min(simd_width_available(), simd_cap()); }
void cap_simd_width(int lanes) { simd_cap() = lanes; }
#endif

namespace {
// The 16 chunk sums as components: the stress column-major (f_a l_b at a + 3 b), the servo
// stiffness, then sum fn, normal and tangential elastic energy, friction loss.
void components_of(const StepSums& s, double (&a)[16]) {
  for (int c = 0; c < 9; ++c) a[c] = s.stress_Pa(c % 3, c / 3);
  for (int c = 0; c < 3; ++c) a[9 + c] = s.stiffness_Pa[c];
  a[12] = s.sum_normal_force_N;
  a[13] = s.elastic_normal_J;
  a[14] = s.elastic_tangential_J;
  a[15] = s.friction_loss_J;
}
// The chunk sums from the accumulators' 16 components.
StepSums step_sums(const double (&a)[16]) {
  StepSums s;
  for (int c = 0; c < 9; ++c) s.stress_Pa(c % 3, c / 3) = a[c];
  s.stiffness_Pa = Vec3(a[9], a[10], a[11]);
  s.sum_normal_force_N = a[12];
  s.elastic_normal_J = a[13];
  s.elastic_tangential_J = a[14];
  s.friction_loss_J = a[15];
  return s;
}
}  // namespace

// One lane: the loop for machines without AVX2 (or DEM_SIMD=0) and for the pairs left over after
// the last full block of a vector loop.
namespace one_lane {
namespace {
using namespace scalar_lanes;

struct Accumulator {
  double acc[16];
  explicit Accumulator(const StepSums& start) { components_of(start, acc); }
  StepSums sums() const { return step_sums(acc); }
  void add(const V (&comp)[16], int first_group = 0) {
    for (int c = 4 * first_group; c < 16; ++c) acc[c] += comp[c];
  }
};

// sum[index] += v (or -= v).
template <bool Subtract>
inline void scatter(Sum4* sum, const std::uint32_t* index, const V3& v) {
  double* s = sum[*index].v;
  if constexpr (Subtract) {
    s[0] -= v.x, s[1] -= v.y, s[2] -= v.z;
  } else {
    s[0] += v.x, s[1] += v.y, s[2] += v.z;
  }
}

#include "dynamics/kernel_simd_pairs.inc"

}  // namespace
}  // namespace one_lane

#ifdef __clang__
#pragma clang attribute push(__attribute__((target("avx2"))), apply_to = function)
#else
#pragma GCC push_options
#pragma GCC target("avx2")
#endif
namespace avx2 {
namespace {

using V = __m256d;     // four lanes: four consecutive pairs, or four consecutive particles
using Mask = __m256d;  // all bits set in the lanes where a condition holds
struct V3 {
  V x, y, z;
};
constexpr std::size_t lanes = 4;

inline V splat(double a) { return _mm256_set1_pd(a); }
inline V zero() { return _mm256_setzero_pd(); }
inline Mask no_lanes() { return _mm256_setzero_pd(); }
inline V select(Mask m, V if_true, V if_false) { return _mm256_blendv_pd(if_false, if_true, m); }
inline V keep(Mask m, V a) { return _mm256_and_pd(m, a); }  // a where m, else +0.0
inline Mask both(Mask a, Mask b) { return _mm256_and_pd(a, b); }
inline Mask either(Mask a, Mask b) { return _mm256_or_pd(a, b); }
inline Mask nonzero(V a) { return _mm256_cmp_pd(a, zero(), _CMP_NEQ_UQ); }  // true for NaN
inline unsigned bits(Mask m) { return static_cast<unsigned>(_mm256_movemask_pd(m)); }
inline Mask not_ge(V a, V b) { return _mm256_cmp_pd(a, b, _CMP_NGE_UQ); }
inline Mask greater(V a, V b) { return _mm256_cmp_pd(a, b, _CMP_GT_OQ); }
inline Mask greater_equal(V a, V b) { return _mm256_cmp_pd(a, b, _CMP_GE_OQ); }
inline Mask less(V a, V b) { return _mm256_cmp_pd(a, b, _CMP_LT_OQ); }
inline V sqrt_of(V a) { return _mm256_sqrt_pd(a); }
inline void store_lanes(double* out, V a) { _mm256_storeu_pd(out, a); }
inline V load_lanes(const double* in) { return _mm256_loadu_pd(in); }

// Four consecutive Vec3 (12 doubles, x0 y0 z0 x1 | y1 z1 x2 y2 | z2 x3 y3 z3) to and from lanes.
inline V3 load(const Vec3* p) {
  const double* d = p->data();
  const V in0 = _mm256_loadu_pd(d), in1 = _mm256_loadu_pd(d + 4), in2 = _mm256_loadu_pd(d + 8);
  const V a = _mm256_permute2f128_pd(in0, in1, 0x30);  // x0 y0 | x2 y2
  const V c = _mm256_permute2f128_pd(in0, in2, 0x21);  // z0 x1 | z2 x3
  const V b = _mm256_permute2f128_pd(in1, in2, 0x30);  // y1 z1 | y3 z3
  return {_mm256_shuffle_pd(a, c, 0xA), _mm256_shuffle_pd(a, b, 0x5), _mm256_shuffle_pd(c, b, 0xA)};
}
inline void store(Vec3* p, const V3& v) {
  double* d = p->data();
  const V a = _mm256_unpacklo_pd(v.x, v.y);         // x0 y0 | x2 y2
  const V c = _mm256_shuffle_pd(v.z, v.x, 0xA);     // z0 x1 | z2 x3
  const V b = _mm256_unpackhi_pd(v.y, v.z);         // y1 z1 | y3 z3
  _mm256_storeu_pd(d, _mm256_permute2f128_pd(a, c, 0x20));
  _mm256_storeu_pd(d + 4, _mm256_permute2f128_pd(b, a, 0x30));
  _mm256_storeu_pd(d + 8, _mm256_permute2f128_pd(c, b, 0x31));
}
// Particle values of four pairs, base[index[p]] in lane p. Built from 128-bit and 64-bit loads:
// on the machine this was tuned on (AMD EPYC), gathers were slower (4,000 steps of shear of
// the 8,000-sphere mu = 0.5 packing: 2.86 s with gathers, 2.70 s with these loads).
DEM_GATHER_INLINE inline V3 gather(const Vec3* base, const std::uint32_t* index) {
  const double *a = base[index[0]].data(), *b = base[index[1]].data(), *c = base[index[2]].data(),
               *d = base[index[3]].data();
  const V ac = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(a)), _mm_loadu_pd(c), 1);  // xa ya | xc yc
  const V bd = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(b)), _mm_loadu_pd(d), 1);  // xb yb | xd yd
  const __m128d z_ab = _mm_loadh_pd(_mm_load_sd(a + 2), b + 2), z_cd = _mm_loadh_pd(_mm_load_sd(c + 2), d + 2);
  return {_mm256_unpacklo_pd(ac, bd), _mm256_unpackhi_pd(ac, bd),
          _mm256_insertf128_pd(_mm256_castpd128_pd256(z_ab), z_cd, 1)};
}
DEM_GATHER_INLINE inline V gather(const double* base, const std::uint32_t* index) {
  return _mm256_setr_pd(base[index[0]], base[index[1]], base[index[2]], base[index[3]]);
}

// A 4 x 4 transpose: given four components c0..c3 of four items (lane p = item p), the four
// items' rows (row[p] lane q = component q of item p).
struct Rows {
  V row[4];
};
inline Rows transpose(V c0, V c1, V c2, V c3) {
  const V t0 = _mm256_unpacklo_pd(c0, c1), t1 = _mm256_unpackhi_pd(c0, c1);
  const V t2 = _mm256_unpacklo_pd(c2, c3), t3 = _mm256_unpackhi_pd(c2, c3);
  return {{_mm256_permute2f128_pd(t0, t2, 0x20), _mm256_permute2f128_pd(t1, t3, 0x20),
           _mm256_permute2f128_pd(t0, t2, 0x31), _mm256_permute2f128_pd(t1, t3, 0x31)}};
}

// The 16 chunk sums as four vectors, component c in acc[c / 4], lane c % 4: the stress
// column-major (f_a l_b at a + 3 b), the servo stiffness, then sum fn, normal and tangential
// elastic energy, friction loss. Each pair's 16 values are added in pair order (contacts are
// counted by the caller).
struct Accumulator {
  V acc[4];

  explicit Accumulator(const StepSums& start) {
    alignas(32) double a[16];
    components_of(start, a);
    for (int g = 0; g < 4; ++g) acc[g] = _mm256_load_pd(a + 4 * g);
  }

  StepSums sums() const {
    alignas(32) double a[16];
    for (int g = 0; g < 4; ++g) _mm256_store_pd(a + 4 * g, acc[g]);
    return step_sums(a);
  }
  // Adds four pairs' values, given per component (comp[c] holds the four pairs' values of
  // component c), pair by pair. Groups before `first_group` are zero and skipped.
  void add(const V (&comp)[16], int first_group = 0) {
    for (int g = first_group; g < 4; ++g) {
      const Rows r = transpose(comp[4 * g], comp[4 * g + 1], comp[4 * g + 2], comp[4 * g + 3]);
      acc[g] = (((acc[g] + r.row[0]) + r.row[1]) + r.row[2]) + r.row[3];
    }
  }
};

// sum[index[p]] += lane p of v (or -=), lane by lane: each pair's force as one row (x, y, z, 0),
// one 256-bit load, add and store per particle. Every lane, in contact or not: a lane out of
// contact adds +0.0, which leaves a sum unchanged (the sums are never -0.0; see PairForces).
template <bool Subtract>
inline void scatter(Sum4* sum, const std::uint32_t* index, const V3& v) {
  const Rows r = transpose(v.x, v.y, v.z, zero());
  for (std::size_t p = 0; p < 4; ++p) {
    double* s = sum[index[p]].v;
    const V old = _mm256_load_pd(s);
    _mm256_store_pd(s, Subtract ? old - r.row[p] : old + r.row[p]);
  }
}

#include "contact/lane_ops.inc"
#include "dynamics/kernel_simd_pairs.inc"

// PeriodicCell::wrap, one axis of four particles; clears the lanes of `inside` that stay outside.
inline V wrap(V x, V& inside) {
  const V one = splat(1.0);
  x = x + keep(less(x, zero()), one);
  x = x - keep(greater_equal(x, one), one);
  inside = both(inside, both(greater_equal(x, zero()), less(x, one)));
  return x;
}

// ParticleLoop::gather with each pair's force and torque read as four doubles, one 256-bit load
// and one add each (the fourth lane carries the next entry's first component and is dropped;
// PairLoop gives the arrays a spare entry): lanes 0-2 add exactly what the scalar gather adds, in
// the same order. Stores the net force in net[i] and the torque in *torque.
template <bool Rotate, class DampingPolicy, bool Sheared>
inline void gather_net(const ParticleLoop<Rotate, DampingPolicy, Sheared>& loop, std::size_t i, Vec3* torque) {
  V f = zero(), t = zero();
  for (std::uint32_t m = loop.second_begin[i]; m < loop.second_begin[i + 1]; ++m) {
    const std::uint32_t k = loop.second_pairs[m];
    f = f + _mm256_loadu_pd(loop.pair_force[k].data());
    if constexpr (Rotate) t = t - _mm256_loadu_pd(loop.torque_j[k].data());
  }
  for (std::uint32_t k = loop.first_begin[i]; k < loop.first_begin[i + 1]; ++k) {
    f = f - _mm256_loadu_pd(loop.pair_force[k].data());
    if constexpr (Rotate) t = t - _mm256_loadu_pd(loop.torque_i[k].data());
  }
  auto put = [](Vec3& out, V a) {
    _mm_storeu_pd(out.data(), _mm256_castpd256_pd128(a));
    _mm_store_sd(out.data() + 2, _mm256_extractf128_pd(a, 1));
  };
  put(loop.net[i], f);
  if constexpr (Rotate) put(*torque, t);
}

// The particles [begin, end) of one chunk, viscous or local damping: ParticleLoop::update four
// particles at a time. In batches of up to 16 blocks of four: the net forces and torques are
// gathered one particle at a time (pair order), then the blocks are moved. `ok` is cleared if a
// particle cannot be wrapped back into the cell.
// The damped leapfrog update of four particles' velocities (or spins, `rot`) from v_old under the
// force f: ViscousDamping::velocity / spin and LocalDamping::velocity / spin, lane by lane.
inline V3 damped_update(const ViscousDamping& d, bool rot, std::size_t ib, const V3& v_old, const V3& f) {
  const V a = _mm256_loadu_pd((rot ? d.a_rot : d.a).data() + ib), c = _mm256_loadu_pd((rot ? d.b_rot : d.b).data() + ib);
  return a * v_old + c * f;
}
// LocalDamping::damped, one component: f - (alpha |f|) sign(v), sign(NaN) = 0 as in the scalar code.
inline V local_damped(V f, V v, V alpha) {
  const V abs_f = _mm256_andnot_pd(splat(-0.0), f);
  const V sign = select(greater(v, zero()), splat(1.0), select(less(v, zero()), splat(-1.0), zero()));
  return f - (alpha * abs_f) * sign;
}
inline V3 damped_update(const LocalDamping& d, bool rot, std::size_t ib, const V3& v_old, const V3& f) {
  const V alpha = splat(rot ? d.alpha_rot : d.alpha);
  const V step = _mm256_loadu_pd((rot ? d.dt_over_I : d.dt_over_m).data() + ib);
  return v_old + step * V3{local_damped(f.x, v_old.x, alpha), local_damped(f.y, v_old.y, alpha),
                           local_damped(f.z, v_old.z, alpha)};
}

template <bool Rotate, class DampingPolicy, bool Sheared>
void particle_chunk(const ParticleLoop<Rotate, DampingPolicy, Sheared>& loop, std::size_t begin, std::size_t end,
                         MotionSums& out, bool& ok) {
  constexpr std::size_t batch = 16;  // blocks
  Vec3 torque[4 * batch];
  V acc = zero();  // twice: kinetic_half_step, kinetic_centred, damping_loss; 0
  V speed2_max = zero();
  V inside = _mm256_castsi256_pd(_mm256_set1_epi64x(-1));
  const DampingPolicy& damping = loop.damping;
  const V dt = splat(loop.dt);
  const V dtLx = splat(loop.dt_over_L[0]), dtLy = splat(loop.dt_over_L[1]), dtLz = splat(loop.dt_over_L[2]);
  const V inv_Ly = splat(loop.inv_L[1]), inv_Lz = splat(loop.inv_L[2]);  // Sheared only
  const V t_xy = splat(loop.tilt[0]), t_xz = splat(loop.tilt[1]), t_yz = splat(loop.tilt[2]);
  const bool scattered = !Rotate && loop.scattered;  // the pair loop summed the forces (PairForces)
  std::size_t i = begin;
  while (i + 4 <= end) {
    const std::size_t n_blocks = std::min(batch, (end - i) / 4);
    if (!scattered) {
      for (std::size_t q = 0; q < 4 * n_blocks; ++q) gather_net(loop, i + q, torque + q);
    }
    for (std::size_t b = 0; b < n_blocks; ++b) {
      const std::size_t ib = i + 4 * b;
      V3 f;
      if (scattered) {  // the four particles' sums, taken (left zero) and transposed into lanes
        Sum4* sum = loop.scattered + ib;
        const Rows c = transpose(_mm256_load_pd(sum[0].v), _mm256_load_pd(sum[1].v), _mm256_load_pd(sum[2].v),
                                 _mm256_load_pd(sum[3].v));
        for (int q = 0; q < 4; ++q) _mm256_store_pd(sum[q].v, zero());
        f = {c.row[0], c.row[1], c.row[2]};
        store(loop.net + ib, f);
      } else {
        f = load(loop.net + ib);
      }
      const V3 v_old = load(loop.v + ib);
      const V3 v_new = damped_update(damping, false, ib, v_old, f);
      store(loop.v + ib, v_new);
      const V3 s = load(loop.s + ib);
      if constexpr (Sheared) {  // ParticleLoop::fractional_step
        const V uz = v_new.z * inv_Lz, vy = v_new.y - t_yz * uz, uy = vy * inv_Ly;
        const V vx = v_new.x - (t_xy * uy + t_xz * uz);
        store(loop.s + ib, {wrap(s.x + vx * dtLx, inside), wrap(s.y + vy * dtLy, inside), wrap(s.z + v_new.z * dtLz, inside)});
      } else {
        store(loop.s + ib, {wrap(s.x + v_new.x * dtLx, inside), wrap(s.y + v_new.y * dtLy, inside),
                             wrap(s.z + v_new.z * dtLz, inside)});
      }
      const V m = _mm256_loadu_pd(loop.mass + ib);
      const V speed2 = dot(v_new, v_new), twice_ke_new = m * speed2;
      speed2_max = _mm256_max_pd(speed2_max, speed2);
      const Rows moved = transpose(twice_ke_new, m * dot(v_old, v_new),
                                   dt * dot(f, v_old + v_new) - (twice_ke_new - m * dot(v_old, v_old)), zero());
      if constexpr (Rotate) {
        const V3 t = load(torque + 4 * b), w_old = load(loop.omega + ib);
        const V3 w_new = damped_update(damping, true, ib, w_old, t);
        store(loop.omega + ib, w_new);
        const V I = _mm256_loadu_pd(loop.inertia + ib);
        const V twice_rot_new = I * dot(w_new, w_new);
        const Rows spun = transpose(zero(), I * dot(w_old, w_new),
                                    dt * dot(t, w_old + w_new) - (twice_rot_new - I * dot(w_old, w_old)), zero());
        for (int p = 0; p < 4; ++p) acc = (acc + moved.row[p]) + spun.row[p];
      } else {
        for (int p = 0; p < 4; ++p) acc = acc + moved.row[p];
      }
    }
    i += 4 * n_blocks;
  }
  alignas(32) double sums[4], speeds[4];
  _mm256_store_pd(sums, acc);
  _mm256_store_pd(speeds, speed2_max);
  out = {sums[0], sums[1], sums[2], std::max(std::max(speeds[0], speeds[1]), std::max(speeds[2], speeds[3]))};
  ok = _mm256_movemask_pd(inside) == 0xF;
  ok &= loop.move(i, end, out);  // the last particles, one by one
}

}  // namespace
}  // namespace avx2
#ifdef __clang__
#pragma clang attribute pop
#else
#pragma GCC pop_options
#endif

#ifdef __clang__
#pragma clang attribute push(__attribute__((target("avx512f"))), apply_to = function)
#else
#pragma GCC push_options
#pragma GCC target("avx512f")
#endif
// GCC 12's AVX-512 intrinsics fill unused lanes from _mm512_undefined_pd(), which it then reports
// as (maybe) uninitialised.
#pragma GCC diagnostic push
#ifndef __clang__
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#pragma GCC diagnostic ignored "-Wuninitialized"
#endif
namespace avx512 {
namespace {

// Eight lanes, built on the four-lane primitives for loads, stores and gathers: 4,000 steps of
// shear of the 8,000-sphere bench packing, one thread, six interleaved runs each, minimum user
// time 1.42 s instead of 1.70 s with four lanes (mu = 0.5), 0.88 s instead of 1.04 s (mu = 0).
using V = __m512d;
using Mask = __mmask8;  // bit p: lane p
struct V3 {
  V x, y, z;
};
constexpr std::size_t lanes = 8;

inline V splat(double a) { return _mm512_set1_pd(a); }
inline V zero() { return _mm512_setzero_pd(); }
inline Mask no_lanes() { return 0; }
inline V select(Mask m, V if_true, V if_false) { return _mm512_mask_blend_pd(m, if_false, if_true); }
inline V keep(Mask m, V a) { return _mm512_maskz_mov_pd(m, a); }  // a where m, else +0.0
inline Mask both(Mask a, Mask b) { return static_cast<Mask>(a & b); }
inline Mask either(Mask a, Mask b) { return static_cast<Mask>(a | b); }
inline Mask nonzero(V a) { return _mm512_cmp_pd_mask(a, zero(), _CMP_NEQ_UQ); }  // true for NaN
inline unsigned bits(Mask m) { return m; }
inline Mask not_ge(V a, V b) { return _mm512_cmp_pd_mask(a, b, _CMP_NGE_UQ); }
inline Mask greater(V a, V b) { return _mm512_cmp_pd_mask(a, b, _CMP_GT_OQ); }
inline Mask greater_equal(V a, V b) { return _mm512_cmp_pd_mask(a, b, _CMP_GE_OQ); }
inline V sqrt_of(V a) { return _mm512_sqrt_pd(a); }
inline void store_lanes(double* out, V a) { _mm512_storeu_pd(out, a); }
inline V load_lanes(const double* in) { return _mm512_loadu_pd(in); }

inline __m256d low(V a) { return _mm512_castpd512_pd256(a); }
inline __m256d high(V a) { return _mm512_extractf64x4_pd(a, 1); }
inline V join(__m256d lo, __m256d hi) { return _mm512_insertf64x4(_mm512_castpd256_pd512(lo), hi, 1); }
inline V3 join(const avx2::V3& lo, const avx2::V3& hi) { return {join(lo.x, hi.x), join(lo.y, hi.y), join(lo.z, hi.z)}; }

inline V3 load(const Vec3* p) { return join(avx2::load(p), avx2::load(p + 4)); }
inline void store(Vec3* p, const V3& v) {
  avx2::store(p, {low(v.x), low(v.y), low(v.z)});
  avx2::store(p + 4, {high(v.x), high(v.y), high(v.z)});
}
DEM_GATHER_INLINE inline V3 gather(const Vec3* base, const std::uint32_t* index) {
  return join(avx2::gather(base, index), avx2::gather(base, index + 4));
}
DEM_GATHER_INLINE inline V gather(const double* base, const std::uint32_t* index) {
  return join(avx2::gather(base, index), avx2::gather(base, index + 4));
}
template <bool Subtract>
inline void scatter(Sum4* sum, const std::uint32_t* index, const V3& v) {
  avx2::scatter<Subtract>(sum, index, {low(v.x), low(v.y), low(v.z)});
  avx2::scatter<Subtract>(sum, index + 4, {high(v.x), high(v.y), high(v.z)});
}

// An 8 x 8 transpose: given eight components c[0..7] of eight pairs (lane p = pair p), the pairs'
// rows (row[p] lane k = component k of pair p).
struct Rows8 {
  V row[8];
};
inline Rows8 transpose(const V* c) {
  const __m512i even = _mm512_setr_epi64(0, 1, 8, 9, 4, 5, 12, 13), odd = _mm512_setr_epi64(2, 3, 10, 11, 6, 7, 14, 15);
  V t[8], u[8];
  for (int k = 0; k < 8; k += 2) t[k] = _mm512_unpacklo_pd(c[k], c[k + 1]), t[k + 1] = _mm512_unpackhi_pd(c[k], c[k + 1]);
  for (int k = 0; k < 8; k += 4) {  // u[k]: pairs 0 4, u[k+1]: 2 6, u[k+2]: 1 5, u[k+3]: 3 7 of components k..k+3
    u[k] = _mm512_permutex2var_pd(t[k], even, t[k + 2]), u[k + 1] = _mm512_permutex2var_pd(t[k], odd, t[k + 2]);
    u[k + 2] = _mm512_permutex2var_pd(t[k + 1], even, t[k + 3]), u[k + 3] = _mm512_permutex2var_pd(t[k + 1], odd, t[k + 3]);
  }
  Rows8 r;
  const int pair_of[4] = {0, 2, 1, 3};  // u[j] holds pairs pair_of[j] and pair_of[j] + 4
  for (int j = 0; j < 4; ++j) {
    r.row[pair_of[j]] = _mm512_shuffle_f64x2(u[j], u[j + 4], 0x44);
    r.row[pair_of[j] + 4] = _mm512_shuffle_f64x2(u[j], u[j + 4], 0xEE);
  }
  return r;
}

// The 16 chunk sums as two vectors, component c in acc[c / 8], lane c % 8 (the components of
// avx2::Accumulator); each pair's values are added in pair order.
struct Accumulator {
  V acc[2];

  explicit Accumulator(const StepSums& start) {
    alignas(64) double a[16];
    components_of(start, a);
    acc[0] = _mm512_load_pd(a), acc[1] = _mm512_load_pd(a + 8);
  }

  StepSums sums() const {
    alignas(64) double a[16];
    _mm512_store_pd(a, acc[0]);
    _mm512_store_pd(a + 8, acc[1]);
    return step_sums(a);
  }
  // As avx2::Accumulator::add, eight pairs. `first_group` counts groups of four components: with
  // 3, components 0-11 are zero and need not be set.
  void add(const V (&comp)[16], int first_group = 0) {
    for (int g = first_group / 2; g < 2; ++g) {
      V c[8];
      for (int k = 0; k < 8; ++k) c[k] = 8 * g + k < 4 * first_group ? zero() : comp[8 * g + k];
      const Rows8 r = transpose(c);
      V a = acc[g];
      for (int p = 0; p < 8; ++p) a = a + r.row[p];
      acc[g] = a;
    }
  }
};

#include "contact/lane_ops.inc"
#include "dynamics/kernel_simd_pairs.inc"

}  // namespace
}  // namespace avx512
#pragma GCC diagnostic pop
#ifdef __clang__
#pragma clang attribute pop
#else
#pragma GCC pop_options
#endif

template <class Law, class DampingPolicy, bool Sheared>
MotionSums forces_and_motion(int simd_lanes, const Law& law, const DampingPolicy& damping, Particles& p,
                             const PeriodicCell& cell, const PairList& pairs, ContactHistory& history,
                             const PairIndex& index, const CellRates& rates, double dt, PairForces& out,
                             StepSums& sums, std::vector<Vec3>& force, const PreviousHalf& previous) {
  PairLoop<Law, Sheared> gathered_pairs(law, p, cell, pairs, history, rates, dt, out, previous);
  ParticleLoop<Law::rotates, DampingPolicy, Sheared> gathered_moves(damping, p, cell, index, out, force, dt);
  // On one thread, a law without torques adds into the particles' sums (PairForces), up to
  // `scatter_max_particles`.
  PairLoop<Law, Sheared> scattered_pairs = gathered_pairs;
  ParticleLoop<Law::rotates, DampingPolicy, Sheared> scattered_moves = gathered_moves;
  if constexpr (!Law::rotates) {
    if (p.size() <= scatter_max_particles) scattered_pairs.scattered = scattered_moves.scattered = out.scattered_sums(p.size());
  }
  if constexpr (Law::damped) out.previous_dashpot_sums.assign(out.chunk_sums.size(), 0.0);
  const auto pair_chunk = [&](std::size_t c, std::size_t begin, std::size_t end, bool serial) {
    const PairLoop<Law, Sheared>& pair_loop = serial ? scattered_pairs : gathered_pairs;
    std::conditional_t<Law::damped, DashpotSums, StepSums> chunk;  // a law with dashpots: also the step before's second half
    std::size_t k = begin;  // pairs before k done by the vector loop
    if (simd_lanes == 8) k = begin + (end - begin) / 8 * 8, avx512::chunk(pair_loop, begin, k, chunk);
    if (simd_lanes == 4) k = begin + (end - begin) / 4 * 4, avx2::chunk(pair_loop, begin, k, chunk);
    one_lane::chunk(pair_loop, k, end, chunk);
    out.chunk_sums[c] = chunk;
    if constexpr (Law::damped) out.previous_dashpot_sums[c] = chunk.previous;
  };
  const auto move_chunk = [&](std::size_t c, std::size_t begin, std::size_t end, bool serial) {
    const ParticleLoop<Law::rotates, DampingPolicy, Sheared>& particle_loop = serial ? scattered_moves : gathered_moves;
    MotionSums chunk;  // sums of twice the energies; halved by total_of_chunks
    bool ok = true;
    if (simd_lanes) {
      avx2::particle_chunk(particle_loop, begin, end, chunk, ok);
    } else {
      const ParticleLoop<Law::rotates, DampingPolicy, Sheared> local = particle_loop;  // its pointers stay in registers
      ok = local.move(begin, end, chunk);
    }
    out.motion_sums[c] = chunk;
    return ok;
  };
  const bool wrapped = sweep_chunks(index, pair_chunk, move_chunk);
  sums = total_of_chunks(out.chunk_sums, cell);
  return total_of_chunks(out.motion_sums, wrapped);
}

template <class Law, bool Sheared>
double dashpot_second_half_as(int simd_lanes, const DashpotWork& w, const PairIndex& index) {
  // The pair chunks of sweep_chunks, each summed from zero, then added in chunk order: what the
  // next step's pair loop books (total_of_chunks).
  double total = 0;
  for (std::ptrdiff_t c = 0; c < chunk_count(index.first_begin.size() - 1); ++c) {
    const auto [begin, end] = pair_chunk_range(index, c);
    double lost = 0;
    std::size_t k = begin;  // pairs before k done by the vector loop
    if (simd_lanes == 8) k = begin + (end - begin) / 8 * 8, lost = avx512::dashpot_work<Law, Sheared>(w, begin, k, lost);
    if (simd_lanes == 4) k = begin + (end - begin) / 4 * 4, lost = avx2::dashpot_work<Law, Sheared>(w, begin, k, lost);
    total += one_lane::dashpot_work<Law, Sheared>(w, k, end, lost);
  }
  return total;
}

template <class Law>
double dashpot_second_half(int simd_lanes, const Particles& p, const PeriodicCell& cell, const PairList& pairs, const PairIndex& index,
                           const PairForces& out, const CellRates& rates, const Mat3& back, double dt) {
  const DashpotWork w{components_at(out.dashpot_force), out.dashpot_distance.data(), pairs.first.data(), pairs.second.data(), p.s.data(), p.radius.data(),
                      p.v.data(), p.omega.data(), cell.lengths(), cell.tilts(), rates.axial, rates.shear, back, dt};
  // The next evaluation's kernel: sheared if the cell is tilted or shearing (Simulation's step).
  const bool sheared = cell.sheared() || rates.shears();
  return 0.5 * dt * (sheared ? dashpot_second_half_as<Law, true>(simd_lanes, w, index) : dashpot_second_half_as<Law, false>(simd_lanes, w, index));
}

// forces_and_motion for every law a scene can choose, both damping forms, orthorhombic and
// sheared, and dashpot_second_half for a law with dashpots: the table's addresses make the
// compiler emit each instantiation for dynamics/simulation.cpp to call. Each law is emitted by
// one of three units: this one the laws of the studies (normal part LinearNormal or HertzNormal),
// dynamics/kernel_simd_dashpot.cpp the laws with contact dashpots, dynamics/kernel_simd_other.cpp
// every other law (a new law lands there with no change here). GCC's inlining budget is per unit: with the dashpot laws in this one it stopped
// inlining Accumulator::add into the other laws' loops (2-3 % slower); apart, the studies' laws'
// code is what it was without them, whatever laws are added.
#ifndef DEM_KERNEL_UNIT
#define DEM_KERNEL_UNIT 0
#endif
#if DEM_KERNEL_UNIT == 0
#define DEM_KERNEL_STEPS steps_of_study_laws
#elif DEM_KERNEL_UNIT == 1
#define DEM_KERNEL_STEPS steps_of_dashpot_laws
#else
#define DEM_KERNEL_STEPS steps_of_other_laws
#endif
namespace {
template <class Law>
constexpr int kernel_unit() {
  using Normal = typename Law::NormalLaw;
  if constexpr (Law::damped) return 1;
  else if constexpr (std::is_same_v<Normal, LinearNormal> || std::is_same_v<Normal, HertzNormal>) return 0;
  else return 2;
}
template <class Law>
auto steps_of() {
  if constexpr (kernel_unit<Law>() == DEM_KERNEL_UNIT && Law::damped) {
    return std::make_tuple(&forces_and_motion<Law, ViscousDamping, false>, &forces_and_motion<Law, ViscousDamping, true>,
                           &forces_and_motion<Law, LocalDamping, false>, &forces_and_motion<Law, LocalDamping, true>,
                           &dashpot_second_half<Law>);
  } else if constexpr (kernel_unit<Law>() == DEM_KERNEL_UNIT) {
    return std::make_tuple(&forces_and_motion<Law, ViscousDamping, false>, &forces_and_motion<Law, ViscousDamping, true>,
                           &forces_and_motion<Law, LocalDamping, false>, &forces_and_motion<Law, LocalDamping, true>);
  } else {
    return std::tuple<>{};
  }
}
template <class Variant>
struct StepsOfEveryLaw;
template <class... Laws>
struct StepsOfEveryLaw<std::variant<Laws...>> {
  static auto table() { return std::tuple_cat(steps_of<Laws>()...); }
};
}  // namespace
extern const decltype(StepsOfEveryLaw<AnyContactLaw>::table()) DEM_KERNEL_STEPS;
const decltype(StepsOfEveryLaw<AnyContactLaw>::table()) DEM_KERNEL_STEPS = StepsOfEveryLaw<AnyContactLaw>::table();

}  // namespace dem
