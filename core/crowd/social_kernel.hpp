#pragma once
// The vectorised inner loop of the social force model: LightSFM's agent–agent force for a batch
// of neighbours of one agent, in single precision.
#include <cstdint>

namespace socsim::crowd {

// LightSFM's social force (the Moussaïd et al. 2009 form) on a batch of neighbours, in single
// precision and without branches so that the loop vectorises. Per pair: e = unit vector to the
// neighbour, t = λ(v_i − v_j) + e, B = γ|t|, θ = angle from t to e, and
//   f = A·(−exp(−d/B − (n′Bθ)²)·t̂ − sign(θ)·exp(−d/B − (nBθ)²)·t̂⊥).
// Inputs are relative: d = (x_j − x_i), dv = v_i − v_j; tie = separation direction used when d = 0.
struct SocialParams {
  float lambda, gamma, inv_gamma, n, n_prime, factor;
};

// Pair forces leave the kernel as integers in units of 2^-20 m/s²: integer sums are exact and
// associative, so the total does not depend on the order neighbours were visited in (the grid
// and the O(N²) reference agree to the bit, whatever the thread count).
inline constexpr float kForceQuantum = 1048576.0f;  // 2^20

inline constexpr int kBatch = 64;
// Batches passed to social_kernel are padded to a multiple of this (the widest vector).
inline constexpr int kBatchLanes = 8;

struct PairBatch {
  alignas(16) float dx[kBatch];
  alignas(16) float dy[kBatch];
  alignas(16) float dvx[kBatch];
  alignas(16) float dvy[kBatch];
  alignas(16) float tie_x[kBatch];
  alignas(16) float tie_y[kBatch];
  alignas(16) std::int32_t fx[kBatch];
  alignas(16) std::int32_t fy[kBatch];
};

// Writes the force on the agent from each of `count` neighbours into fx, fy (units of 2^-20 m/s²).
// On x86-64 CPUs with AVX-512 or AVX2 a hand-written version for that width runs; every other CPU
// runs the portable loop. All give the same bits.
void social_kernel(const SocialParams& p, int count, const float* __restrict dx, const float* __restrict dy,
                   const float* __restrict dvx, const float* __restrict dvy, const float* __restrict tie_x,
                   const float* __restrict tie_y, std::int32_t* __restrict fx, std::int32_t* __restrict fy);

// The portable loop, always available (tests compare it with social_kernel).
void social_kernel_portable(const SocialParams& p, int count, const float* __restrict dx,
                            const float* __restrict dy, const float* __restrict dvx,
                            const float* __restrict dvy, const float* __restrict tie_x,
                            const float* __restrict tie_y, std::int32_t* __restrict fx,
                            std::int32_t* __restrict fy);

// The speed–headway cap over the same batch: the smallest (s_j − ℓ + τ·(v_j − v_i)·e)/T, floored
// at 0, over the neighbours straight ahead — (dx, dy)·e > 0, their centre within `band` of the walking
// line through the agent along the unit direction e, and not walking towards it (v_j·e ≥
// −oncoming, with v_j·e = speed_along − dv·e) — (s_j their centre distance, (v_j − v_i)·e
// = −dv·e how fast they pull away along the walking direction), or `best` when smaller. The
// relative-speed term vanishes in uniform flow (the fundamental diagram depends on ℓ and T only)
// and lets a follower keep up with someone accelerating away, as through a door. A minimum over
// non-negative floats, so the order of the batch does not matter.
float headway_speed_cap(int count, const float* __restrict dx, const float* __restrict dy,
                        const float* __restrict dvx, const float* __restrict dvy, float ex, float ey,
                        float band, float speed_along, float oncoming, float distance, float inv_time,
                        float anticipation, float best);

// Side preference towards oncoming walkers (an addition to LightSFM): over the same batch, the sum
// of the sideways pushes from neighbours ahead ((dx, dy)·e > 0) whose centre lies within `band`
// of the walking line and who walk towards the agent (v_j·e < −oncoming): each pushes with
// factor·exp(−ahead/range) to the agent's right when it is less than `bias` to the right of the
// walking line (so two walkers meeting head-on both step to their right and pass left shoulder to
// left shoulder), and to the left otherwise (it is already passing on the right). Returned in units
// of 2^-20 m/s² along the agent's right-hand direction (e_y, −e_x); an integer sum, so the order of
// the batch does not matter.
std::int64_t oncoming_side_push(int count, const float* __restrict dx, const float* __restrict dy,
                                const float* __restrict dvx, const float* __restrict dvy, float ex, float ey,
                                float band, float speed_along, float oncoming, float bias, float factor,
                                float inv_range);

// Both of the above in one pass over the batch (what the step uses; the results are those of
// headway_speed_cap and oncoming_side_push, bit for bit: tests/core/crowd/neighbour_gather_test.cpp).
// count <= kBatch and side_factor <= 100 m/s² (RoleTable's limit), so per-lane sums fit 32 bits.
struct AheadParams {
  float ex, ey;        // unit walking direction
  float speed_along;   // v_i·e
  float oncoming;      // m/s: v_j·e below −oncoming is walking towards the agent
  float headway_band;  // half-width of the band ahead for the headway cap
  float distance;      // ℓ
  float inv_time;      // 1/T
  float anticipation;  // τ_a
  float side_band;     // half-width of the band for the side push
  float side_bias;
  float side_factor;
  float side_inv_range;
};
struct AheadTerms {
  float speed_cap;         // as headway_speed_cap(…, best)
  std::int64_t side_push;  // as oncoming_side_push
};
AheadTerms ahead_terms(int count, const float* __restrict dx, const float* __restrict dy,
                       const float* __restrict dvx, const float* __restrict dvy, const AheadParams& p,
                       float best);

// social_kernel and ahead_terms over the same batch in one pass (what the step uses): fx, fy as
// social_kernel writes them with their sums, and, when `ahead` is given, the terms
// ahead_terms(count, dx, dy, dvx, dvy, *ahead, best) returns ({best, 0} without), bit for bit
// (tests/core/crowd/neighbour_gather_test.cpp). On CPUs with AVX-512 or AVX2 the hand-written
// kernel computes all of it from the same loads and distances; elsewhere the functions run one
// after the other.
struct BatchTotals {
  AheadTerms ahead;
  std::int64_t fx, fy;  // Σ fx[m], Σ fy[m] (units of 2^-20 m/s²)
};
BatchTotals social_kernel_with_ahead(const SocialParams& p, const AheadParams* ahead, float best, int count,
                                     const float* __restrict dx, const float* __restrict dy,
                                     const float* __restrict dvx, const float* __restrict dvy,
                                     const float* __restrict tie_x, const float* __restrict tie_y,
                                     std::int32_t* __restrict fx, std::int32_t* __restrict fy);

// Each pair once. Where every agent shares the pair terms' parameters (one role, or roles that
// differ only elsewhere), the social force on j from i is exactly minus the force on i from j —
// d and θ are the same, e and t change sign, and every float operation here rounds symmetrically —
// so the step computes each pair (i, j) once, from whichever of the two comes first in the grid's
// order, and gives j the negated force; the headway cap and side push are not antisymmetric and
// are computed for both from the same loads. Lanes may belong to different agents i.
inline constexpr int kLaneSlack = 16;  // the widest kernel's lanes (pair_kernel_lanes())
struct PairLanes {
  // Inputs: the offset x_j − x_i, the relative velocity v_i − v_j, the tie direction (as PairBatch),
  // and for each side its walking direction ((0, 0) without a goal), v·e and headway band
  // (kLaneSlack lanes to spare: core/crowd/neighbour_gather.hpp fills them 8 at a time, and the
  // lanes past the last pair up to the kernel's width are zeroed a whole vector at a time).
  alignas(32) float dx[kBatch + kLaneSlack];
  alignas(32) float dy[kBatch + kLaneSlack];
  alignas(32) float dvx[kBatch + kLaneSlack];
  alignas(32) float dvy[kBatch + kLaneSlack];
  alignas(32) float tie_x[kBatch];
  alignas(32) float tie_y[kBatch];
  alignas(32) float ex_i[kBatch + kLaneSlack];
  alignas(32) float ey_i[kBatch + kLaneSlack];
  alignas(32) float along_i[kBatch + kLaneSlack];
  alignas(32) float band_i[kBatch + kLaneSlack];
  alignas(32) float ex_j[kBatch + kLaneSlack];
  alignas(32) float ey_j[kBatch + kLaneSlack];
  alignas(32) float along_j[kBatch + kLaneSlack];
  alignas(32) float band_j[kBatch + kLaneSlack];
  // Outputs: the social force on i (units of 2^-20 m/s²; j gets minus it), and for each side the
  // headway cap as the bits of a non-negative float (INT32_MAX where j is not ahead of i in the
  // band) and the side push (as oncoming_side_push: along that side's right-hand direction).
  alignas(32) std::int32_t fx[kBatch];
  alignas(32) std::int32_t fy[kBatch];
  alignas(32) std::int32_t cap_i[kBatch];
  alignas(32) std::int32_t cap_j[kBatch];
  alignas(32) std::int32_t push_i[kBatch];
  alignas(32) std::int32_t push_j[kBatch];
};
// The ahead terms' parameters shared by both sides (AheadParams without the per-agent ones).
struct PairAheadParams {
  float oncoming, distance, inv_time, anticipation, side_band, side_bias, side_factor, side_inv_range;
};
// Lanes [0, count) of b, count a multiple of pair_kernel_lanes() (pad with zeros: inert). For each lane
// the results are, bit for bit, what social_kernel and ahead_terms give for i's batch (fx, fy,
// cap_i, push_i) and for j's (−fx, −fy, cap_j, push_j): tests/core/crowd/neighbour_gather_test.cpp.
void pair_kernel(const SocialParams& p, const PairAheadParams& a, int count, PairLanes& b);
// The lanes pair_kernel runs at a time on this CPU (16 with AVX-512, else 8): pad counts to it.
int pair_kernel_lanes();
void pair_kernel_portable(const SocialParams& p, const PairAheadParams& a, int count, PairLanes& b);

}  // namespace socsim::crowd
