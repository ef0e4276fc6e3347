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

bool simd_available() {
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

bool simd_enabled() { return simd_available() && simd_switch(); }
void enable_simd(bool on) { simd_switch() = on; }

namespace {

using V = __m256d;  // four lanes: four consecutive pairs, or four consecutive particles

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
// Particle values of four pairs, base[index[p]] in lane p. Built from 128-bit and 64-bit loads:
// on the machine this was tuned on (AMD EPYC), AVX2 gathers were slower (4,000 steps of shear of
// the 8,000-sphere mu = 0.5 packing: 2.86 s with gathers, 2.70 s with these loads).
AVX2 inline V3 gather(const Vec3* base, const std::uint32_t* index) {
  const double *a = base[index[0]].data(), *b = base[index[1]].data(), *c = base[index[2]].data(),
               *d = base[index[3]].data();
  const V ac = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(a)), _mm_loadu_pd(c), 1);  // xa ya | xc yc
  const V bd = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(b)), _mm_loadu_pd(d), 1);  // xb yb | xd yd
  const __m128d z_ab = _mm_loadh_pd(_mm_load_sd(a + 2), b + 2), z_cd = _mm_loadh_pd(_mm_load_sd(c + 2), d + 2);
  return {_mm256_unpacklo_pd(ac, bd), _mm256_unpackhi_pd(ac, bd),
          _mm256_insertf128_pd(_mm256_castpd128_pd256(z_ab), z_cd, 1)};
}
AVX2 inline V gather(const double* base, const std::uint32_t* index) {
  return _mm256_setr_pd(base[index[0]], base[index[1]], base[index[2]], base[index[3]]);
}

// A 4 x 4 transpose: given four components c0..c3 of four items (lane p = item p), the four
// items' rows (row[p] lane q = component q of item p).
struct Rows {
  V row[4];
};
AVX2 inline Rows transpose(V c0, V c1, V c2, V c3) {
  const V t0 = _mm256_unpacklo_pd(c0, c1), t1 = _mm256_unpackhi_pd(c0, c1);
  const V t2 = _mm256_unpacklo_pd(c2, c3), t3 = _mm256_unpackhi_pd(c2, c3);
  return {{_mm256_permute2f128_pd(t0, t2, 0x20), _mm256_permute2f128_pd(t1, t3, 0x20),
           _mm256_permute2f128_pd(t0, t2, 0x31), _mm256_permute2f128_pd(t1, t3, 0x31)}};
}

// The 16 chunk sums as four vectors, component c in acc[c / 4], lane c % 4: the stress
// column-major (f_a l_b at a + 3 b), the servo stiffness, then sum fn, normal and tangential
// elastic energy, friction loss. Each pair's 16 values are added in pair order.
struct Accumulator {
  V acc[4];
  std::size_t contacts = 0;

  AVX2 Accumulator() : acc{zero(), zero(), zero(), zero()} {}

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
  // component c), pair by pair. Groups before `first_group` are zero and skipped.
  AVX2 void add(const V (&comp)[16], int first_group = 0) {
    for (int g = first_group; g < 4; ++g) {
      const Rows r = transpose(comp[4 * g], comp[4 * g + 1], comp[4 * g + 2], comp[4 * g + 3]);
      acc[g] = (((acc[g] + r.row[0]) + r.row[1]) + r.row[2]) + r.row[3];
    }
  }
};

// One block of four pairs between the phases of `chunk`.
struct Block {
  V3 l, n;             // branch vector, unit normal
  V ri, rj, overlap, fn;
  V touch;             // lanes in contact
  // Frictional only:
  V3 u_old, du;        // the spring turned into the tangent plane, and its increment v_t dt
  V3 u, ft;            // the spring after this step (capped), the tangential force
  V old2, lost, sliding;  // |spring|^2 before this step, energy the cap took, lanes that slid
};

// The pairs [begin, end) of one chunk: blocks of four pairs, in batches of up to 16 blocks that go
// through four phases (geometry; turning and loading the springs; the Coulomb cap; forces and
// sums). Each phase is a short loop whose iterations are independent, so the processor overlaps
// the divide and square-root chains of several blocks. With the whole pair in one loop body, one
// block's chain of them was the bottleneck: on the 8,000-sphere mu = 0.5 packing, 4,000 steps of
// shear took 2.70 s in one loop, 2.00 s in three phases, 1.86 s in four.
template <class Friction>
AVX2 void chunk(const PairLoop<Friction>& loop, std::size_t begin, std::size_t end, StepSums& out) {
  constexpr bool frictional = Friction::has_tangential;
  constexpr std::size_t batch = 16;  // blocks
  Block blocks[batch];
  Accumulator acc;
  const Vec3& L = loop.cell.lengths();
  const V Lx = splat(L[0]), Ly = splat(L[1]), Lz = splat(L[2]);
  const V kn = splat(loop.law.kn), half = splat(0.5);
  const Vec3& rate = loop.strain_rate;
  const V rate_x = splat(rate[0]), rate_y = splat(rate[1]), rate_z = splat(rate[2]);
  double ks_ = 0, mu_ = 0;
  if constexpr (frictional) ks_ = loop.law.friction.ks, mu_ = loop.law.friction.mu;
  const V ks = splat(ks_), minus_ks = splat(-ks_), ks2 = splat(ks_ * ks_), half_ks = splat(0.5 * ks_), mu = splat(mu_);
  const V dt = splat(loop.dt);
  const V3 none{zero(), zero(), zero()};
  std::size_t k = begin;
  while (k + 4 <= end) {
    const std::size_t n_blocks = std::min(batch, (end - k) / 4);
    // Geometry: branch vector, normal, overlap, normal force.
    for (std::size_t b = 0; b < n_blocks; ++b) {
      Block& B = blocks[b];
      const std::uint32_t *ii = loop.first + k + 4 * b, *jj = loop.second + k + 4 * b;
      const V3 si = gather(loop.s, ii), sj = gather(loop.s, jj);
      B.l = {branch(si.x, sj.x, Lx), branch(si.y, sj.y, Ly), branch(si.z, sj.z, Lz)};
      const V dist2 = dot(B.l, B.l);
      B.ri = gather(loop.radius, ii), B.rj = gather(loop.radius, jj);
      const V rsum = B.ri + B.rj;
      B.touch = _mm256_cmp_pd(dist2, rsum * rsum, _CMP_NGE_UQ);  // !(dist2 >= rsum^2), as the scalar test
      const V dist = _mm256_sqrt_pd(dist2);
      B.n = {B.l.x / dist, B.l.y / dist, B.l.z / dist};
      B.overlap = rsum - dist;
      B.fn = kn * B.overlap;
    }
    // Tangential springs (Coulomb::tangential, lane by lane): turned into the tangent plane, then
    // loaded by the tangential displacement of this step.
    if constexpr (frictional) {
      for (std::size_t b = 0; b < n_blocks; ++b) {
        Block& B = blocks[b];
        const std::size_t kb = k + 4 * b;
        V3 u = load4(loop.spring + kb);
        B.old2 = dot(u, u);
        if (_mm256_movemask_pd(B.touch) == 0) {  // no contact in these four pairs
          B.u = none, B.ft = none, B.lost = zero(), B.sliding = zero();
          continue;
        }
        const V3& n = B.n;
        const std::uint32_t *ii = loop.first + kb, *jj = loop.second + kb;
        const V arm_i = B.ri - half * B.overlap, arm_j = B.rj - half * B.overlap;
        const V3 vi = gather(loop.v, ii), vj = gather(loop.v, jj);
        const V3 wi = gather(loop.omega, ii), wj = gather(loop.omega, jj);
        const V3 spin = cross(arm_i * wi + arm_j * wj, n);
        const V3 v_rel{((vj.x - vi.x) - rate_x * B.l.x) - spin.x, ((vj.y - vi.y) - rate_y * B.l.y) - spin.y,
                       ((vj.z - vi.z) - rate_z * B.l.z) - spin.z};
        const V3 v_t = v_rel - dot(n, v_rel) * n;
        const V had_spring = _mm256_cmp_pd(B.old2, zero(), _CMP_GT_OQ);
        const V3 turned = u - dot(n, u) * n;
        const V new2 = dot(turned, turned);
        const V rescale = _mm256_and_pd(had_spring, _mm256_cmp_pd(new2, zero(), _CMP_GT_OQ));
        u = select(had_spring, select(rescale, _mm256_sqrt_pd(B.old2 / new2) * turned, turned), u);
        B.du = dt * v_t;
        B.u_old = u;
        B.u = u + B.du;
      }
      // The Coulomb cap.
      for (std::size_t b = 0; b < n_blocks; ++b) {
        Block& B = blocks[b];
        if (_mm256_movemask_pd(B.touch) == 0) continue;
        const V3 du = B.du, u_old = B.u_old, u = B.u;
        const V limit = mu * B.fn;
        B.sliding = _mm256_and_pd(_mm256_cmp_pd(ks2 * dot(u, u), limit * limit, _CMP_GE_OQ), B.touch);
        const V norm = _mm256_sqrt_pd(dot(u, u));
        const V cap = select(_mm256_cmp_pd(norm, zero(), _CMP_GT_OQ), limit / (ks * norm), zero());
        const V3 capped = cap * u;
        B.lost = keep(B.sliding, half_ks * (dot(u_old + capped, du) - (dot(capped, capped) - dot(u_old, u_old))));
        B.u = keep(B.touch, select(B.sliding, capped, u));
        B.ft = minus_ks * B.u;
      }
    }
    // Forces, torques and the chunk sums, pair by pair in pair order.
    for (std::size_t b = 0; b < n_blocks; ++b) {
      const Block& B = blocks[b];
      const std::size_t kb = k + 4 * b;
      const V touch = B.touch;
      const int touching = _mm256_movemask_pd(touch);
      V comp[16];
      comp[12] = zero(), comp[13] = zero(), comp[14] = zero(), comp[15] = zero();
      V3 f = B.fn * B.n;
      if constexpr (frictional) {
        const int slid = _mm256_movemask_pd(B.sliding);
        for (int p = 0; p < 4; ++p) loop.sliding_flag[kb + p] = static_cast<std::uint8_t>((slid >> p) & 1);
        store4(loop.spring + kb, B.u);
        comp[15] = select(touch, B.lost, half_ks * B.old2);  // an opening contact loses its spring
        if (touching == 0) {
          store4(loop.pair_force + kb, none);
          store4(loop.torque_i + kb, none);
          store4(loop.torque_j + kb, none);
          acc.add(comp, 3);
          continue;
        }
        comp[14] = keep(touch, (half * dot(B.ft, B.ft)) / ks);
        f = f + B.ft;
        const V3 nxft = cross(B.n, B.ft);
        const V arm_i = B.ri - half * B.overlap, arm_j = B.rj - half * B.overlap;
        store4(loop.torque_i + kb, keep(touch, arm_i * nxft));
        store4(loop.torque_j + kb, keep(touch, arm_j * nxft));
      } else if (touching == 0) {
        store4(loop.pair_force + kb, none);
        continue;
      }
      f = keep(touch, f);
      store4(loop.pair_force + kb, f);
      const V3& l = B.l;
      const V lx = keep(touch, l.x), ly = keep(touch, l.y), lz = keep(touch, l.z);
      comp[0] = f.x * lx, comp[1] = f.y * lx, comp[2] = f.z * lx;
      comp[3] = f.x * ly, comp[4] = f.y * ly, comp[5] = f.z * ly;
      comp[6] = f.x * lz, comp[7] = f.y * lz, comp[8] = f.z * lz;
      const V nlx = B.n.x * l.x, nly = B.n.y * l.y, nlz = B.n.z * l.z;
      comp[9] = keep(touch, kn * (nlx * nlx));
      comp[10] = keep(touch, kn * (nly * nly));
      comp[11] = keep(touch, kn * (nlz * nlz));
      comp[12] = keep(touch, B.fn);
      comp[13] = keep(touch, (half * B.fn) * B.overlap);
      acc.add(comp);
      acc.contacts += static_cast<std::size_t>(std::popcount(static_cast<unsigned>(touching)));
    }
    k += 4 * n_blocks;
  }
  out = acc.sums();
  for (; k < end; ++k) loop.pair(k, out);  // the last pairs of the list, one by one
}

// PeriodicCell::wrap, one axis of four particles; clears the lanes of `inside` that stay outside.
AVX2 inline V wrap(V x, V& inside) {
  const V one = splat(1.0);
  x = x + keep(_mm256_cmp_pd(x, zero(), _CMP_LT_OQ), one);
  x = x - keep(_mm256_cmp_pd(x, one, _CMP_GE_OQ), one);
  inside = _mm256_and_pd(inside, _mm256_and_pd(_mm256_cmp_pd(x, zero(), _CMP_GE_OQ), _mm256_cmp_pd(x, one, _CMP_LT_OQ)));
  return x;
}

// The particles [begin, end) of one chunk under viscous damping: ParticleLoop::update four
// particles at a time. In batches of up to 16 blocks of four: the net forces and torques are
// gathered one particle at a time (pair order), then the blocks are moved. `ok` is cleared if a
// particle cannot be wrapped back into the cell.
template <bool Rotate>
AVX2 void particle_chunk(const ParticleLoop<Rotate, ViscousDamping>& loop, std::size_t begin, std::size_t end,
                         MotionSums& out, bool& ok) {
  constexpr std::size_t batch = 16;  // blocks
  Vec3 torque[4 * batch];
  V acc = zero();  // twice: kinetic_half_step, kinetic_centred, damping_loss; 0
  V inside = _mm256_castsi256_pd(_mm256_set1_epi64x(-1));
  const ViscousDamping& damping = loop.damping;
  const V dt = splat(loop.dt);
  const V dtLx = splat(loop.dt_over_L[0]), dtLy = splat(loop.dt_over_L[1]), dtLz = splat(loop.dt_over_L[2]);
  std::size_t i = begin;
  while (i + 4 <= end) {
    const std::size_t n_blocks = std::min(batch, (end - i) / 4);
    for (std::size_t q = 0; q < 4 * n_blocks; ++q) {
      Vec3 f, t;
      loop.gather(i + q, f, t);
      loop.net[i + q] = f;
      torque[q] = t;
    }
    for (std::size_t b = 0; b < n_blocks; ++b) {
      const std::size_t ib = i + 4 * b;
      const V3 f = load4(loop.net + ib), v_old = load4(loop.v + ib);
      const V a = _mm256_loadu_pd(damping.a.data() + ib), c = _mm256_loadu_pd(damping.b.data() + ib);
      const V3 v_new = a * v_old + c * f;
      store4(loop.v + ib, v_new);
      const V3 s = load4(loop.s + ib);
      store4(loop.s + ib, {wrap(s.x + v_new.x * dtLx, inside), wrap(s.y + v_new.y * dtLy, inside),
                           wrap(s.z + v_new.z * dtLz, inside)});
      const V m = _mm256_loadu_pd(loop.mass + ib);
      const V twice_ke_new = m * dot(v_new, v_new);
      const Rows moved = transpose(twice_ke_new, m * dot(v_old, v_new),
                                   dt * dot(f, v_old + v_new) - (twice_ke_new - m * dot(v_old, v_old)), zero());
      if constexpr (Rotate) {
        const V3 t = load4(torque + 4 * b), w_old = load4(loop.omega + ib);
        const V a_rot = _mm256_loadu_pd(damping.a_rot.data() + ib), c_rot = _mm256_loadu_pd(damping.b_rot.data() + ib);
        const V3 w_new = a_rot * w_old + c_rot * t;
        store4(loop.omega + ib, w_new);
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
  alignas(32) double sums[4];
  _mm256_store_pd(sums, acc);
  out = {sums[0], sums[1], sums[2]};
  ok = _mm256_movemask_pd(inside) == 0xF;
  for (; i < end; ++i) {  // the last particles, one by one
    Vec3 f, t;
    loop.gather(i, f, t);
    ok &= loop.update(i, f, t, out);
  }
}

}  // namespace

template <bool Rotate>
MotionSums integrate_simd(const ViscousDamping& damping, Particles& p, const PeriodicCell& cell, const PairIndex& index,
                          PairForces& pf, std::vector<Vec3>& force, double dt) {
  const ParticleLoop<Rotate, ViscousDamping> loop(damping, p, cell, index, pf, force, dt);
  const bool wrapped = for_each_chunk(loop.n, [&](std::size_t c, std::size_t begin, std::size_t end) {
    bool ok = true;
    particle_chunk(loop, begin, end, pf.motion_sums[c], ok);
    return ok;
  });
  return total_of_chunks(pf.motion_sums, wrapped);
}

template MotionSums integrate_simd<true>(const ViscousDamping&, Particles&, const PeriodicCell&, const PairIndex&,
                                         PairForces&, std::vector<Vec3>&, double);
template MotionSums integrate_simd<false>(const ViscousDamping&, Particles&, const PeriodicCell&, const PairIndex&,
                                          PairForces&, std::vector<Vec3>&, double);

template <class Friction>
void compute_forces_simd(const LinearSpring<Friction>& law, const Particles& p, const PeriodicCell& cell,
                         PairList& pairs, const Vec3& strain_rate, double dt, PairForces& out, StepSums& sums) {
  const PairLoop<Friction> loop(law, p, cell, pairs, strain_rate, dt, out);
  for_each_chunk(loop.n_pairs, [&](std::size_t c, std::size_t begin, std::size_t end) {
    chunk(loop, begin, end, out.chunk_sums[c]);
    return true;
  });
  sums = total_of_chunks(out.chunk_sums, cell);
}

template void compute_forces_simd<NoFriction>(const LinearSpring<NoFriction>&, const Particles&, const PeriodicCell&,
                                              PairList&, const Vec3&, double, PairForces&, StepSums&);
template void compute_forces_simd<Coulomb>(const LinearSpring<Coulomb>&, const Particles&, const PeriodicCell&,
                                           PairList&, const Vec3&, double, PairForces&, StepSums&);

}  // namespace dem
