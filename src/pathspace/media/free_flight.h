// Distance sampling and transmittance in one medium along one ray segment (pbrt-v4 ch. 14.1;
// Novak et al. 2018, "Monte Carlo methods for volumetric light transport simulation"):
//  - homogeneous: closed form, the distance drawn from one channel's exponential and weighted by
//    the mixture's density over the three channels (single-sample MIS over RGB);
//  - grid: weighted delta tracking against the per-cell majorants (null-scattering formulation,
//    Miller, Georgiev, Jarosz 2019): at a tentative collision the path scatters, passes on (null
//    collision) or is absorbed with probabilities from the channels' mixture, and the weight carries
//    the per-channel ratios; transmittance by ratio tracking with Russian roulette on small values.
// The channels are mixed in proportion to the path's throughput (Chiang, Kutz, Burley 2016): with
// equal shares, each event's weight may reach 3 in one channel and a long walk in a chromatic medium
// multiplies them into fireflies; weighted by the throughput, a channel the path has lost no longer
// drives the sampling and the weights stay near 1.
// All of it is unbiased; the random numbers come from a stream owned by the path (Pcg32).
#pragma once

#include "pathspace/media/majorant_walk.h"
#include "pathspace/media/media_view.h"
#include "pathspace/sampling/rng.h"

namespace pathspace {

enum class MediumEvent : uint8_t { passed, scattered, absorbed };

struct FreeFlight {
  MediumEvent event = MediumEvent::passed;
  float t = 0.f;       // scattered: where along the ray
  Rgb weight{1.f};     // passed: transmittance / probability; scattered: sigma_s transmittance / density
  float density = 0.f; // scattered in a homogeneous medium: the density of t (MIS with equiangular
                       // sampling, pt_kernel.h); 0 in a grid
};

namespace media_detail {
// exp(-sigma d) per channel, 1 where sigma is 0 (also for an infinite d).
PS_INLINE Rgb beer_lambert(const Rgb& sigma, float d) {
  Rgb out;
  for (int c = 0; c < 3; ++c) out[c] = sigma[c] > 0.f ? expf(-sigma[c] * d) : 1.f;
  return out;
}
PS_INLINE float exponential_step(float sigma, float u) { return -log1pf(-u) / sigma; }
PS_INLINE Rgb nonnegative(const Rgb& c) { return {fmaxf(c.r, 0.f), fmaxf(c.g, 0.f), fmaxf(c.b, 0.f)}; }
PS_INLINE float mix(const Rgb& shares, const Rgb& c) { return shares.r * c.r + shares.g * c.g + shares.b * c.b; }

// The channels' shares of the sampling: the throughput's, or equal ones for a throughput that is
// black or not finite.
PS_INLINE Rgb channel_shares(const Rgb& throughput) {
  const Rgb t = nonnegative(throughput);
  const float sum = t.r + t.g + t.b;
  if (!(sum > 0.f) || !isfinite(sum)) return Rgb(1.f / 3.f);
  return t / sum;
}

// The channel whose share covers u (u in [0, 1)).
PS_INLINE int pick_channel(const Rgb& shares, float u) {
  if (u < shares.r) return 0;
  return u < shares.r + shares.g ? 1 : 2;
}

// The probability that a channel of extinction sigma collides before d (1 for an infinite d).
PS_INLINE float collision_mass(float sigma, float d) { return !(sigma > 0.f) ? 0.f : isinf(d) ? 1.f : -expm1f(-sigma * d); }

// The density of a collision where the transmittance is tr, on a segment d long: the mixture of the
// channels' exponentials (free flight), or of their exponentials truncated to [0, d) (kCollide, the
// scatter branch). The samplers below and scatter_density share it, so MIS sees their own density.
template <bool kCollide>
PS_INLINE float mixture_density(const Rgb& st, const Rgb& tr, float d, const Rgb& shares) {
  if (!kCollide) return mix(shares, st * tr);
  float density = 0.f;
  for (int k = 0; k < 3; ++k) {
    const float mass = collision_mass(st[k], d);
    if (mass > 0.f) density += shares[k] * st[k] * tr[k] / mass;
  }
  return density;
}

// The density of a collision at distance t (from the segment's start) of a segment d long; 0 where
// nothing scatters.
template <bool kCollide>
PS_INLINE float homogeneous_collision_density(const Medium& m, float t, float d, const Rgb& shares) {
  if (is_black(m.albedo) || !(t < d)) return 0.f;
  return mixture_density<kCollide>(m.sigma_t, beer_lambert(m.sigma_t, t), d, shares);
}

PS_INLINE FreeFlight homogeneous_flight(const Medium& m, float tmax, const Rgb& shares, Pcg32& rng) {
  FreeFlight f;
  const Rgb st = m.sigma_t;
  if (is_black(m.albedo)) {  // nothing scatters: the path passes with the transmittance, or not at all
    f.weight = beer_lambert(st, tmax);
    if (is_black(f.weight)) f.event = MediumEvent::absorbed;
    return f;
  }
  const int c = pick_channel(shares, rng.next_float());
  const float u = rng.next_float();
  const float t = st[c] > 0.f ? exponential_step(st[c], u) : kInfinity;
  if (t < tmax) {
    const Rgb tr = beer_lambert(st, t);
    const float density = mixture_density<false>(st, tr, tmax, shares);
    f.event = MediumEvent::scattered;
    f.t = t;
    f.weight = m.albedo * st * tr / density;
    f.density = density;
    return f;
  }
  const Rgb tr = beer_lambert(st, tmax);
  const float p = mix(shares, tr);
  if (!(p > 0.f)) {
    f.event = MediumEvent::absorbed;
    f.weight = Rgb();
    return f;
  }
  f.weight = tr / p;
  return f;
}

// Calls collide(t, sigma_bar) at each tentative collision along `ray` up to tmax: exponential steps
// against the majorant of each cell the ray crosses (media/majorant_walk.h), until it returns false.
template <typename Collide>
PS_INLINE void for_each_tentative_collision(const Medium& m, const float* values, const Ray& ray, float tmax, Pcg32& rng,
                                            Collide collide) {
  MajorantWalk walk(m, values, ray, tmax);
  MajorantSegment seg;
  while (walk.next(&seg)) {
    if (!(seg.sigma > 0.f)) continue;
    float t = seg.t0;
    for (;;) {
      t += exponential_step(seg.sigma, rng.next_float());
      if (!(t < seg.t1)) break;
      if (!collide(t, seg.sigma)) return;
    }
  }
}

PS_INLINE FreeFlight grid_flight(const Medium& m, const float* values, const Ray& ray, float tmax, const Rgb& shares,
                                 Pcg32& rng) {
  FreeFlight f;
  for_each_tentative_collision(m, values, ray, tmax, rng, [&](float t, float sigma) {
    const Vec3 g = grid_point(m, ray.at(t));
    const Rgb st = medium_sigma_t(m, values, g);
    const Rgb ss = medium_albedo(m, values, g) * st;
    const Rgb sn = nonnegative(Rgb(sigma) - st);
    // The shares weigh the path's own weight: a channel's ratio is divided by the mixture, so the
    // weighted sum of the new weights equals that of the old ones in expectation.
    const Rgb sw = shares * f.weight;
    const float norm = sw.r + sw.g + sw.b;
    const Rgb mixw = norm > 0.f ? sw / norm : shares;
    const float ps = mix(mixw, ss) / sigma, pn = mix(mixw, sn) / sigma;
    const float u = rng.next_float();
    if (u < ps) {
      f.event = MediumEvent::scattered;
      f.t = t;
      f.weight *= ss / (sigma * ps);
      return false;
    }
    if (u < ps + pn) {
      f.weight *= sn / (sigma * pn);
      return true;
    }
    f.event = MediumEvent::absorbed;
    f.weight = Rgb();
    return false;
  });
  return f;
}

// A collision on [0, d) always: one channel's exponential truncated to the interval (mass
// 1 - exp(-sigma d) before d), weighted by the mixture's density; absorbed with weight 0 where
// nothing scatters or the picked channel has no collisions (its density is 0 there, so the estimate
// stays unbiased).
PS_INLINE FreeFlight homogeneous_collision(const Medium& m, float d, const Rgb& shares, Pcg32& rng) {
  FreeFlight f;
  f.event = MediumEvent::absorbed;
  f.weight = Rgb();
  const Rgb st = m.sigma_t;
  const int c = pick_channel(shares, rng.next_float());
  const float u = rng.next_float();
  if (is_black(m.albedo)) return f;
  const float mass = collision_mass(st[c], d);
  if (!(mass > 0.f)) return f;
  const float t = -log1pf(-u * mass) / st[c];
  if (!(t < d)) return f;
  const Rgb tr = beer_lambert(st, t);
  const float density = mixture_density<true>(st, tr, d, shares);
  f.event = MediumEvent::scattered;
  f.t = t;
  f.weight = m.albedo * st * tr / density;
  f.density = density;
  return f;
}

PS_INLINE Rgb grid_transmittance(const Medium& m, const float* values, const Ray& ray, float tmax, Pcg32& rng) {
  Rgb tr(1.f);
  for_each_tentative_collision(m, values, ray, tmax, rng, [&](float t, float sigma) {
    const Rgb st = medium_sigma_t(m, values, grid_point(m, ray.at(t)));
    tr *= nonnegative(Rgb(sigma) - st) / sigma;
    if (max_component(tr) < 0.05f) {  // Russian roulette: survive with 1/4, weighted by 4
      if (rng.next_float() < 0.75f) {
        tr = Rgb();
        return false;
      }
      tr *= 4.f;
    }
    return true;
  });
  return tr;
}

// A flight along `ray` over [ray.tmin, tmax): in a homogeneous medium the closed form (kCollide: the
// collision drawn before tmax, homogeneous_collision), in a grid weighted delta tracking.
template <bool kCollide>
PS_INLINE FreeFlight flight(const MediaView& media, int32_t medium, const Ray& ray, float tmax, const Rgb& throughput,
                            Pcg32& rng) {
  const Medium& m = media.media[medium];
  const Rgb shares = channel_shares(throughput);
  if (m.type == MediumType::homogeneous) {
    const float d = tmax - ray.tmin;
    FreeFlight f = kCollide ? homogeneous_collision(m, d, shares, rng) : homogeneous_flight(m, d, shares, rng);
    f.t += ray.tmin;
    return f;
  }
  return grid_flight(m, media.grid_values, ray, tmax, shares, rng);
}
}  // namespace media_detail

// Where the path travelling along `ray` in medium `medium` interacts before `tmax` (the next surface,
// or infinity), and the factor its throughput takes. `throughput`: the path's so far (the channels'
// shares of the sampling; any value gives an unbiased estimate).
PS_INLINE FreeFlight sample_free_flight(const MediaView& media, int32_t medium, const Ray& ray, float tmax,
                                        const Rgb& throughput, Pcg32& rng) {
  return media_detail::flight<false>(media, medium, ray, tmax, throughput, rng);
}

// The transmittance of medium `medium` along `ray` from ray.tmin to tmax (exact for homogeneous
// media, an unbiased estimate for grids).
PS_INLINE Rgb medium_transmittance(const MediaView& media, int32_t medium, const Ray& ray, float tmax, Pcg32& rng) {
  const Medium& m = media.media[medium];
  if (m.type == MediumType::homogeneous) return media_detail::beer_lambert(m.sigma_t, tmax - ray.tmin);
  return media_detail::grid_transmittance(m, media.grid_values, ray, tmax, rng);
}

// Camera-side branches in media (VertexSelection::camera_splits, pt_kernel.h): instead of one free
// flight that either scatters or passes, a path follows both, each weighted so that the two add up
// to the free flight's estimate:
//  - the scatter branch: a collision before tmax, drawn from the truncated exponential in a
//    homogeneous medium (always, where anything scatters); in a grid the free flight, whose "passed"
//    outcome then ends the branch (weight 0);
//  - the pass branch: passes with the transmittance (exact, or ratio tracking in a grid).
// What a pixel sees through fog is then no longer a random pick between the fog and the surface
// behind it: each is filtered at its own vertex.
PS_INLINE bool medium_scatters(const MediaView& media, int32_t medium) {
  const Medium& m = media.media[medium];
  return m.type != MediumType::homogeneous || !is_black(m.albedo);
}

PS_INLINE FreeFlight sample_scatter_branch(const MediaView& media, int32_t medium, const Ray& ray, float tmax,
                                           const Rgb& throughput, Pcg32& rng) {
  FreeFlight f = media_detail::flight<true>(media, medium, ray, tmax, throughput, rng);
  if (f.event == MediumEvent::passed) f = FreeFlight{MediumEvent::absorbed, 0.f, Rgb()};  // a grid's
  return f;
}

// The density with which the free flight (kCollide false) or the scatter branch (true) along `ray`
// up to tmax scatters at t, for a path of throughput `throughput`; 0 in a grid, whose density is not
// known in closed form.
template <bool kCollide>
PS_INLINE float scatter_density(const MediaView& media, int32_t medium, const Ray& ray, float tmax, const Rgb& throughput,
                                float t) {
  const Medium& m = media.media[medium];
  if (m.type != MediumType::homogeneous) return 0.f;
  return media_detail::homogeneous_collision_density<kCollide>(m, t - ray.tmin, tmax - ray.tmin, media_detail::channel_shares(throughput));
}

PS_INLINE FreeFlight sample_pass_branch(const MediaView& media, int32_t medium, const Ray& ray, float tmax, Pcg32& rng) {
  FreeFlight f;
  f.weight = medium_transmittance(media, medium, ray, tmax, rng);
  if (is_black(f.weight)) f.event = MediumEvent::absorbed;
  return f;
}

}  // namespace pathspace
