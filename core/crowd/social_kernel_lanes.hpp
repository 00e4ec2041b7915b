// The hand-written social kernel's body, written once for every x86-64 vector width: included by
// core/crowd/social_kernel.cpp once per instruction set, so no #pragma once. Before each inclusion
// the includer defines
//   SOCSIM_LANES_NAMESPACE  the namespace (inside socsim::crowd's anonymous one) to fill, which
//                           already holds `struct Simd`: the vector type, its lane count,
//                           kInterleave and the few operations below that differ between widths;
//   SOCSIM_LANES_TARGET     the instruction set to compile it for, as in __attribute__((target)).
// A target attribute cannot depend on a template parameter, and GCC and clang refuse to inline an
// intrinsic into a function compiled for less, hence one copy of this text per instruction set
// rather than a template over Simd.
//
// N vectors at a time, their operations interleaved one by one. The compiled loop works on one
// vector at a time: each lane is a chain of ~200 dependent operations (two square roots, three
// divisions, an arctangent and two exponentials), longer than the processor can look ahead, so
// consecutive vectors barely overlap; interleaved vectors keep its units busy (−28 % per pair for
// two AVX-512 vectors, docs/PERFORMANCE.md). Every operation is the portable loop's, in its order,
// with the same rounding (no fused multiply-add): the same bits
// (SocialKernel.HandWrittenKernelEqualsThePortableLoop).

namespace socsim::crowd {
namespace {
namespace SOCSIM_LANES_NAMESPACE {

#define SOCSIM_LANES __attribute__((target(SOCSIM_LANES_TARGET), always_inline)) inline
#define SOCSIM_EACH for (int k = 0; k < N; ++k)

template <int N>
struct Pk {
  typename Simd::vec v[N];
};
template <int N>
struct Mk {
  typename Simd::mask v[N];
};

template <int N>
SOCSIM_LANES Pk<N> splat(float x) {
  Pk<N> r;
  SOCSIM_EACH r.v[k] = Simd::set1(x);
  return r;
}
template <int N>
SOCSIM_LANES Pk<N> operator+(const Pk<N>& a, const Pk<N>& b) {
  Pk<N> r;
  SOCSIM_EACH r.v[k] = Simd::add(a.v[k], b.v[k]);
  return r;
}
template <int N>
SOCSIM_LANES Pk<N> operator-(const Pk<N>& a, const Pk<N>& b) {
  Pk<N> r;
  SOCSIM_EACH r.v[k] = Simd::sub(a.v[k], b.v[k]);
  return r;
}
template <int N>
SOCSIM_LANES Pk<N> operator*(const Pk<N>& a, const Pk<N>& b) {
  Pk<N> r;
  SOCSIM_EACH r.v[k] = Simd::mul(a.v[k], b.v[k]);
  return r;
}
template <int N>
SOCSIM_LANES Pk<N> operator/(const Pk<N>& a, const Pk<N>& b) {
  Pk<N> r;
  SOCSIM_EACH r.v[k] = Simd::div(a.v[k], b.v[k]);
  return r;
}
template <int N>
SOCSIM_LANES Pk<N> operator-(const Pk<N>& a) {  // unary minus: the sign bit flipped
  Pk<N> r;
  SOCSIM_EACH r.v[k] = Simd::neg(a.v[k]);
  return r;
}
template <int N>
SOCSIM_LANES Pk<N> root(const Pk<N>& a) {
  Pk<N> r;
  SOCSIM_EACH r.v[k] = Simd::sqrt(a.v[k]);
  return r;
}
template <int N>
SOCSIM_LANES Mk<N> operator<(const Pk<N>& a, const Pk<N>& b) {
  Mk<N> r;
  SOCSIM_EACH r.v[k] = Simd::less(a.v[k], b.v[k]);
  return r;
}
template <int N>
SOCSIM_LANES Mk<N> operator>(const Pk<N>& a, const Pk<N>& b) {
  Mk<N> r;
  SOCSIM_EACH r.v[k] = Simd::less(b.v[k], a.v[k]);  // a > b is b < a, NaN false in both
  return r;
}
// For finite lanes: max(a, b), min(a, b) (as std::max, std::min) and |a|
template <int N>
SOCSIM_LANES Pk<N> maximum(const Pk<N>& a, const Pk<N>& b) {
  Pk<N> r;
  SOCSIM_EACH r.v[k] = Simd::max(a.v[k], b.v[k]);
  return r;
}
template <int N>
SOCSIM_LANES Pk<N> minimum(const Pk<N>& a, const Pk<N>& b) {
  Pk<N> r;
  SOCSIM_EACH r.v[k] = Simd::min(a.v[k], b.v[k]);
  return r;
}
template <int N>
SOCSIM_LANES Pk<N> magnitude(const Pk<N>& a) {
  Pk<N> r;
  SOCSIM_EACH r.v[k] = Simd::abs(a.v[k]);
  return r;
}
// m ? t : f, lane by lane
template <int N>
SOCSIM_LANES Pk<N> select(const Mk<N>& m, const Pk<N>& t, const Pk<N>& f) {
  Pk<N> r;
  SOCSIM_EACH r.v[k] = Simd::select(m.v[k], t.v[k], f.v[k]);
  return r;
}

template <int N>
SOCSIM_LANES Pk<N> exp_lanes(const Pk<N>& x) {  // fast_expf
  using namespace fast_float;
  const Pk<N> lo = splat<N>(kExpLow);
  const Pk<N> hi = splat<N>(kExpHigh);
  const Pk<N> clamped = maximum(minimum(x, hi), lo);  // the same as fast_expf's selects for finite x
  const Pk<N> shift = splat<N>(kShift);
  const Pk<N> kf = (clamped * splat<N>(kLog2e) + shift) - shift;
  const Pk<N> r = (clamped - kf * splat<N>(kLn2Hi)) - kf * splat<N>(kLn2Lo);
  Pk<N> p = splat<N>(kExpPoly[0]);
  for (std::size_t i = 1; i < std::size(kExpPoly); ++i) p = p * r + splat<N>(kExpPoly[i]);
  Pk<N> scale;
  SOCSIM_EACH scale.v[k] = Simd::exp2_integer(kf.v[k]);
  return select(x < lo, splat<N>(0.0f), p * scale);
}

template <int N>
SOCSIM_LANES Pk<N> atan2_lanes(const Pk<N>& y, const Pk<N>& x) {  // fast_atan2f
  using namespace fast_float;
  const Pk<N> zero = splat<N>(0.0f);
  const Pk<N> one = splat<N>(1.0f);
  const Pk<N> ax = magnitude(x);
  const Pk<N> ay = magnitude(y);
  const Mk<N> x_wider = ax > ay;
  const Pk<N> mx = select(x_wider, ax, ay);
  const Pk<N> mn = select(x_wider, ay, ax);
  const Mk<N> upper = mn > splat<N>(kTanPi8) * mx;
  const Pk<N> t = select(upper, mn - mx, mn) / select(upper, mn + mx, select(mx > zero, mx, one));
  const Pk<N> s = t * t;
  Pk<N> p = splat<N>(kAtanPoly[0]);
  for (std::size_t i = 1; i < std::size(kAtanPoly); ++i) p = p * s + splat<N>(kAtanPoly[i]);
  Pk<N> angle = select(upper, splat<N>(kPi4), zero) + t * p;
  angle = select(ay > ax, splat<N>(kPi2) - angle, angle);
  angle = select(x < zero, splat<N>(kPi) - angle, angle);
  return select(y < zero, -angle, angle);
}

// Running per-lane results of the ahead terms (ahead_terms in social_kernel.cpp): the smallest
// headway cap as the bits of a non-negative float (INT32_MAX where no neighbour counts) and the
// integer sum of the side pushes. A lane sees at most kBatch / kLanes <= 8 neighbours, so its sum
// stays within 32 bits (|push| <= 100·2^20).
struct AheadLanes {
  typename Simd::ivec least, sum;
  typename Simd::ivec fx, fy;  // the running sums of the pair forces (32- or 64-bit lanes)
};

// ahead_terms' lane computation on N vectors (same operations, same order, same bits), for an
// agent walking along (ex, ey) at speed_along with the squared headway band band2 (per lane: the
// pair kernel's lanes belong to different agents), from the kernel's loads and its distance
// d = √(dx² + dy²), which ahead_terms computes the same way: each lane's headway cap (max(raw, 0))
// and whether the neighbour follows in the band or meets the agent, and the side push where it
// meets it. The push's exponential is evaluated only when some lane meets an oncoming walker:
// the others are masked out after it anyway.
template <int N>
struct AheadLaneTerms {
  Pk<N> cap, push;  // push: only when any_meets
  typename Simd::mask follows[N], meets[N];
  bool any_meets;
};
template <int N>
SOCSIM_LANES AheadLaneTerms<N> ahead_lane_terms(const PairAheadParams& a, const Pk<N>& ex, const Pk<N>& ey,
                                                const Pk<N>& speed_along, const Pk<N>& band2, const Pk<N>& ox,
                                                const Pk<N>& oy, const Pk<N>& dvx, const Pk<N>& dvy,
                                                const Pk<N>& d) {
  AheadLaneTerms<N> t;
  const Pk<N> zero = splat<N>(0.0f);
  const Pk<N> ahead = ox * ex + oy * ey;
  const Pk<N> side = ox * ey - oy * ex;
  const Pk<N> closing = dvx * ex + dvy * ey;
  const Pk<N> toward = speed_along - closing;
  const Pk<N> raw = ((d - splat<N>(a.distance)) - splat<N>(a.anticipation) * closing) * splat<N>(a.inv_time);
  t.cap = select(raw < zero, zero, raw);  // std::max(raw, 0.0f)
  const Mk<N> in_front = ahead > zero;
  const Pk<N> side2 = side * side;
  const Pk<N> oncoming = splat<N>(-a.oncoming);
  const Pk<N> side_band2 = splat<N>(a.side_band * a.side_band);
  t.any_meets = false;
  SOCSIM_EACH {
    t.follows[k] = Simd::both(Simd::both(in_front.v[k], Simd::less(side2.v[k], band2.v[k])),
                              Simd::greater_equal(toward.v[k], oncoming.v[k]));
    t.meets[k] = Simd::both(Simd::both(in_front.v[k], Simd::less(side2.v[k], side_band2.v[k])),
                            Simd::less(toward.v[k], oncoming.v[k]));
    t.any_meets = t.any_meets || Simd::any(t.meets[k]);
  }
  if (t.any_meets) {
    const Pk<N> floored = select(ahead < zero, zero, ahead);  // std::max(ahead, 0.0f)
    const Pk<N> magnitude =
        splat<N>(a.side_factor * kForceQuantum) * exp_lanes(-floored * splat<N>(a.side_inv_range));
    t.push = select(side < splat<N>(a.side_bias), magnitude, -magnitude);
  } else {
    t.push = zero;
  }
  return t;
}

// One agent's ahead terms over N vectors of its batch, folded into the running per-lane results.
template <int N>
SOCSIM_LANES void ahead_lanes(const AheadParams& a, const Pk<N>& ox, const Pk<N>& oy, const Pk<N>& dvx,
                              const Pk<N>& dvy, const Pk<N>& d, AheadLanes& acc) {
  const PairAheadParams shared{a.oncoming,  a.distance,  a.inv_time,    a.anticipation,
                               a.side_band, a.side_bias, a.side_factor, a.side_inv_range};
  const AheadLaneTerms<N> t =
      ahead_lane_terms<N>(shared, splat<N>(a.ex), splat<N>(a.ey), splat<N>(a.speed_along),
                          splat<N>(a.headway_band * a.headway_band), ox, oy, dvx, dvy, d);
  SOCSIM_EACH acc.least =
      Simd::imin(acc.least, Simd::iselect(t.follows[k], Simd::bits(t.cap.v[k]), Simd::iset1(INT32_MAX)));
  if (!t.any_meets) return;
  SOCSIM_EACH acc.sum =
      Simd::iadd(acc.sum, Simd::iselect(t.meets[k], Simd::truncate(t.push.v[k]), Simd::iset1(0)));
}

// The social force (in units of 2^-20 m/s², before truncation) on the agent from N vectors of
// neighbours at (rx, ry), tie direction (ux, uy), relative velocity (vx, vy), distance d.
template <int N>
struct Forces {
  Pk<N> x, y;
};
template <int N>
SOCSIM_LANES Forces<N> social_lanes(const SocialParams& p, const Pk<N>& rx, const Pk<N>& ry, const Pk<N>& ux,
                                    const Pk<N>& uy, const Pk<N>& vx, const Pk<N>& vy, const Pk<N>& d) {
  const Pk<N> zero = splat<N>(0.0f);
  const Pk<N> one = splat<N>(1.0f);
  const Pk<N> tiny = splat<N>(1e-30f);
  const Pk<N> inv_d = one / select(d < tiny, tiny, d);
  const Pk<N> ex = rx * inv_d + ux;
  const Pk<N> ey = ry * inv_d + uy;
  const Pk<N> lambda = splat<N>(p.lambda);
  const Pk<N> ix = lambda * vx + ex;
  const Pk<N> iy = lambda * vy + ey;
  const Pk<N> il2 = ix * ix + iy * iy;
  const Mk<N> live = il2 > splat<N>(1e-12f);
  const Pk<N> il = root(il2);
  const Pk<N> floor = splat<N>(1e-6f);
  const Pk<N> inv_il = one / select(il < floor, floor, il);
  const Pk<N> tx = ix * inv_il;
  const Pk<N> ty = iy * inv_il;
  const Pk<N> b = splat<N>(p.gamma) * il;
  const Pk<N> theta = atan2_lanes(ix * ey - iy * ex, ix * ex + iy * ey);
  const Pk<N> base = -d * inv_il * splat<N>(p.inv_gamma);
  const Pk<N> nb = splat<N>(p.n) * b * theta;
  const Pk<N> npb = splat<N>(p.n_prime) * b * theta;
  const Pk<N> along = -exp_lanes(base - npb * npb);
  const Pk<N> sign = select(theta > zero, one, select(theta < zero, splat<N>(-1.0f), zero));
  const Pk<N> side = -sign * exp_lanes(base - nb * nb);
  // 0 where not live: every other factor is finite, so the force is ±0 there, truncated to 0.
  const Pk<N> scale = select(live, splat<N>(p.factor * kForceQuantum), zero);
  const Pk<N> gx = scale * (along * tx - side * ty);
  const Pk<N> gy = scale * (along * ty + side * tx);
  return {gx, gy};
}

// Lanes [m, m + L·N) of the batch (L = Simd::kLanes), those at or past `count` read as 0 and not
// written; count − m > L·(N − 1), so every vector has a lane in the batch.
template <int N, bool Narrow>
SOCSIM_LANES void kernel_lanes(const SocialParams& p, const AheadParams* ahead, AheadLanes& acc, int m,
                               int count, const float* dx, const float* dy, const float* dvx,
                               const float* dvy, const float* tie_x, const float* tie_y, std::int32_t* fx,
                               std::int32_t* fy) {
  typename Simd::lanes in[N];
  SOCSIM_EACH in[k] = Simd::first(count - m - Simd::kLanes * k);
  Pk<N> rx, ry, ux, uy, vx, vy;
  SOCSIM_EACH {
    const int o = m + Simd::kLanes * k;
    rx.v[k] = Simd::load(in[k], dx + o);
    ry.v[k] = Simd::load(in[k], dy + o);
    ux.v[k] = Simd::load(in[k], tie_x + o);
    uy.v[k] = Simd::load(in[k], tie_y + o);
    vx.v[k] = Simd::load(in[k], dvx + o);
    vy.v[k] = Simd::load(in[k], dvy + o);
  }
  const Pk<N> d = root(rx * rx + ry * ry);
  if (ahead != nullptr) ahead_lanes(*ahead, rx, ry, vx, vy, d, acc);
  const Forces<N> g = social_lanes<N>(p, rx, ry, ux, uy, vx, vy, d);
  SOCSIM_EACH {
    const int o = m + Simd::kLanes * k;
    // Lanes outside the batch read zeros and give 0 (not live), so they add nothing to the sums.
    const typename Simd::ivec qx = Simd::truncate(g.x.v[k]);
    const typename Simd::ivec qy = Simd::truncate(g.y.v[k]);
    Simd::store_ints(in[k], fx + o, qx);
    Simd::store_ints(in[k], fy + o, qy);
    if constexpr (Narrow) {  // 32-bit lanes (they cannot overflow: social_kernel_lanes)
      acc.fx = Simd::iadd(acc.fx, qx);
      acc.fy = Simd::iadd(acc.fy, qy);
    } else {
      acc.fx = Simd::widen_add(acc.fx, qx);
      acc.fy = Simd::widen_add(acc.fy, qy);
    }
  }
}

// Lanes [m, count): N vectors at a time while the batch fills more than N − 1, then the rest with
// fewer, so no vector runs without a lane in the batch.
template <int N, bool Narrow>
SOCSIM_LANES void kernel_from(const SocialParams& p, const AheadParams* ahead, AheadLanes& acc, int m,
                              int count, const float* dx, const float* dy, const float* dvx, const float* dvy,
                              const float* tie_x, const float* tie_y, std::int32_t* fx, std::int32_t* fy) {
  for (; count - m > Simd::kLanes * (N - 1); m += Simd::kLanes * N)
    kernel_lanes<N, Narrow>(p, ahead, acc, m, count, dx, dy, dvx, dvy, tie_x, tie_y, fx, fy);
  if constexpr (N > 1)
    kernel_from<N - 1, Narrow>(p, ahead, acc, m, count, dx, dy, dvx, dvy, tie_x, tie_y, fx, fy);
}

// One side's ahead terms for N vectors of pairs, each lane with its own walking direction (ex,
// ey), speed along it and headway band, stored per lane at cap + m and push + m (not reduced;
// INT32_MAX and 0 in the lanes that neither follow nor meet, so the step sums every lane).
template <int N>
SOCSIM_LANES void pair_ahead_lanes(const PairAheadParams& a, const Pk<N>& ex, const Pk<N>& ey,
                                   const Pk<N>& speed_along, const Pk<N>& band, const Pk<N>& ox,
                                   const Pk<N>& oy, const Pk<N>& dvx, const Pk<N>& dvy, const Pk<N>& d,
                                   std::int32_t* cap_out, std::int32_t* push_out, int m) {
  const AheadLaneTerms<N> t = ahead_lane_terms<N>(a, ex, ey, speed_along, band * band, ox, oy, dvx, dvy, d);
  SOCSIM_EACH {
    const int o = m + Simd::kLanes * k;
    Simd::istore(cap_out + o, Simd::iselect(t.follows[k], Simd::bits(t.cap.v[k]), Simd::iset1(INT32_MAX)));
    Simd::istore(push_out + o, t.any_meets
                                   ? Simd::iselect(t.meets[k], Simd::truncate(t.push.v[k]), Simd::iset1(0))
                                   : Simd::iset1(0));
  }
}

// N whole vectors from p (every lane in the batch).
template <int N>
SOCSIM_LANES Pk<N> load_lanes(const typename Simd::lanes& all, const float* p) {
  Pk<N> r;
  SOCSIM_EACH r.v[k] = Simd::load(all, p + Simd::kLanes * k);
  return r;
}

// Lanes [m, m + L·N) of a batch of pairs (pair_kernel): the force on i, both sides' ahead terms.
template <int N>
SOCSIM_LANES void pair_lanes(const SocialParams& p, const PairAheadParams& a, int m, PairLanes& b) {
  const typename Simd::lanes all = Simd::first(Simd::kLanes);
  const Pk<N> rx = load_lanes<N>(all, b.dx + m);
  const Pk<N> ry = load_lanes<N>(all, b.dy + m);
  const Pk<N> vx = load_lanes<N>(all, b.dvx + m);
  const Pk<N> vy = load_lanes<N>(all, b.dvy + m);
  const Pk<N> d = root(rx * rx + ry * ry);
  pair_ahead_lanes<N>(a, load_lanes<N>(all, b.ex_i + m), load_lanes<N>(all, b.ey_i + m),
                      load_lanes<N>(all, b.along_i + m), load_lanes<N>(all, b.band_i + m), rx, ry, vx, vy, d,
                      b.cap_i, b.push_i, m);
  // j's view: the offset and the relative velocity reversed (exactly: a sign flip), the same d.
  pair_ahead_lanes<N>(a, load_lanes<N>(all, b.ex_j + m), load_lanes<N>(all, b.ey_j + m),
                      load_lanes<N>(all, b.along_j + m), load_lanes<N>(all, b.band_j + m), -rx, -ry, -vx, -vy,
                      d, b.cap_j, b.push_j, m);
  const Forces<N> g =
      social_lanes<N>(p, rx, ry, load_lanes<N>(all, b.tie_x + m), load_lanes<N>(all, b.tie_y + m), vx, vy, d);
  SOCSIM_EACH {
    const int o = m + Simd::kLanes * k;
    Simd::store_ints(all, b.fx + o, Simd::truncate(g.x.v[k]));
    Simd::store_ints(all, b.fy + o, Simd::truncate(g.y.v[k]));
  }
}

template <int N>
SOCSIM_LANES void pair_from(const SocialParams& p, const PairAheadParams& a, int m, int count, PairLanes& b) {
  for (; count - m >= Simd::kLanes * N; m += Simd::kLanes * N) pair_lanes<N>(p, a, m, b);
  if constexpr (N > 1) pair_from<N - 1>(p, a, m, count, b);
}

__attribute__((target(SOCSIM_LANES_TARGET))) void pair_kernel_lanes(const SocialParams& p,
                                                                    const PairAheadParams& a, int count,
                                                                    PairLanes& b) {
  pair_from<Simd::kPairInterleave>(p, a, 0, count, b);
}

__attribute__((target(SOCSIM_LANES_TARGET))) BatchTotals social_kernel_lanes(
    const SocialParams& p, const AheadParams* ahead, float best, int count, const float* dx, const float* dy,
    const float* dvx, const float* dvy, const float* tie_x, const float* tie_y, std::int32_t* fx,
    std::int32_t* fy) {
  AheadLanes acc{Simd::iset1(std::bit_cast<std::int32_t>(best)), Simd::iset1(0), Simd::iset1(0),
                 Simd::iset1(0)};
  // Each lane sums at most kBatch / kLanes pair forces, each below 1.5·factor·2^20 in magnitude
  // (|along|, |side| <= 1, |t| = 1, with rounding to spare): with the usual factors (below about
  // 170 m/s² on 8 lanes) the sums fit 32-bit lanes, widened once at the end.
  const bool narrow =
      p.factor * kForceQuantum * 1.5f * static_cast<float>(kBatch / Simd::kLanes) < 2147483648.0f;
  if (narrow)
    kernel_from<Simd::kInterleave, true>(p, ahead, acc, 0, count, dx, dy, dvx, dvy, tie_x, tie_y, fx, fy);
  else
    kernel_from<Simd::kInterleave, false>(p, ahead, acc, 0, count, dx, dy, dvx, dvy, tie_x, tie_y, fx, fy);
  alignas(64) std::int32_t least[Simd::kLanes];
  alignas(64) std::int32_t sums[Simd::kLanes];
  // The lanes as stored (32-bit integers), read as the integers they hold: 32-bit sums, or the
  // two halves of each 64-bit sum (low word first, two's complement).
  alignas(64) std::int32_t force_x[Simd::kLanes];
  alignas(64) std::int32_t force_y[Simd::kLanes];
  Simd::istore(least, acc.least);
  Simd::istore(sums, acc.sum);
  Simd::istore(force_x, acc.fx);
  Simd::istore(force_y, acc.fy);
  BatchTotals t{};
  std::int32_t cap = least[0];
  for (int l = 0; l < Simd::kLanes; ++l) {
    cap = std::min(cap, least[l]);
    t.ahead.side_push += sums[l];
  }
  t.ahead.speed_cap = std::bit_cast<float>(cap);
  if (narrow) {
    for (int l = 0; l < Simd::kLanes; ++l) {
      t.fx += force_x[l];
      t.fy += force_y[l];
    }
  } else {
    const auto wide = [](const std::int32_t* w, int l) {
      return static_cast<std::int64_t>(
          (static_cast<std::uint64_t>(static_cast<std::uint32_t>(w[2 * l + 1])) << 32u) |
          static_cast<std::uint32_t>(w[2 * l]));
    };
    for (int l = 0; l < Simd::kLanes / 2; ++l) {
      t.fx += wide(force_x, l);
      t.fy += wide(force_y, l);
    }
  }
  return t;
}

#undef SOCSIM_EACH
#undef SOCSIM_LANES

}  // namespace SOCSIM_LANES_NAMESPACE
}  // namespace
}  // namespace socsim::crowd
