// The segments of a ray through a grid medium's coarse majorant cells, in order (a 3D DDA, Amanatides
// and Woo 1987; pbrt-v4's DDAMajorantIterator): each segment [t0, t1) carries a bound of sigma_t
// over its cell, so delta and ratio tracking (media/free_flight.h) take short steps only where the
// medium is dense. Distances are the ray's parameter (world lengths for a unit direction).
#pragma once

#include "pathspace/geometry/ray.h"
#include "pathspace/media/grid_lookup.h"

namespace pathspace {

struct MajorantSegment {
  float t0 = 0.f, t1 = 0.f;
  float sigma = 0.f;  // the bound of every channel's sigma_t in [t0, t1)
};

class MajorantWalk {
 public:
  // The part of `ray` in [ray.tmin, tmax] inside the medium's box.
  PS_HD MajorantWalk(const Medium& m, const float* values, const Ray& ray, float tmax) : values_(values) {
    const GridShape& s = m.majorants;
    scale_ = max_component(m.sigma_t);
    offset_ = s.offset;
    const Vec3 o = grid_point(m, ray.o), d = grid_vector(m, ray.d);
    float t_in = ray.tmin, t_out = tmax;
    for (int a = 0; a < 3; ++a) {  // the slabs of the unit cube
      if (d[a] == 0.f) {
        if (o[a] < 0.f || o[a] > 1.f) t_out = -1.f;
        continue;
      }
      float ta = (0.f - o[a]) / d[a], tb = (1.f - o[a]) / d[a];
      if (ta > tb) {
        const float tmp = ta;
        ta = tb;
        tb = tmp;
      }
      t_in = fmaxf(t_in, ta);
      t_out = fminf(t_out, tb);
    }
    t_ = t_in;
    t_end_ = t_out;
    if (!(t_in < t_out)) return;
    const uint32_t res[3] = {s.nx, s.ny, s.nz};
    nx_ = s.nx;
    ny_ = s.ny;
    const Vec3 p = o + d * t_in;
    for (int a = 0; a < 3; ++a) {
      const float f = p[a] * float(res[a]);
      int c = int(f);
      c = c < 0 ? 0 : (c >= int(res[a]) ? int(res[a]) - 1 : c);
      cell_[a] = c;
      if (d[a] == 0.f) {
        next_[a] = kInfinity;
        delta_[a] = 0.f;
        step_[a] = 0;
        stop_[a] = -2;
      } else if (d[a] > 0.f) {
        next_[a] = t_in + (float(c + 1) / float(res[a]) - p[a]) / d[a];
        delta_[a] = 1.f / (float(res[a]) * d[a]);
        step_[a] = 1;
        stop_[a] = int(res[a]);
      } else {
        next_[a] = t_in + (float(c) / float(res[a]) - p[a]) / d[a];
        delta_[a] = -1.f / (float(res[a]) * d[a]);
        step_[a] = -1;
        stop_[a] = -1;
      }
    }
  }

  // The next segment, or false past the box.
  PS_HD bool next(MajorantSegment* seg) {
    if (!(t_ < t_end_)) return false;
    const int a = next_[0] < next_[1] ? (next_[0] < next_[2] ? 0 : 2) : (next_[1] < next_[2] ? 1 : 2);
    const float t1 = fminf(t_end_, next_[a]);
    const size_t cell = (size_t(cell_[2]) * ny_ + size_t(cell_[1])) * nx_ + size_t(cell_[0]);
    seg->t0 = t_;
    seg->t1 = t1;
    seg->sigma = scale_ * values_[offset_ + cell];
    t_ = t1;
    cell_[a] += step_[a];
    if (cell_[a] == stop_[a]) t_ = t_end_;
    next_[a] += delta_[a];
    return true;
  }

 private:
  const float* values_;
  float scale_ = 0.f;
  uint32_t offset_ = 0, nx_ = 0, ny_ = 0;
  float t_ = 0.f, t_end_ = -1.f;
  int cell_[3] = {0, 0, 0}, step_[3] = {0, 0, 0}, stop_[3] = {0, 0, 0};
  float next_[3] = {0.f, 0.f, 0.f}, delta_[3] = {0.f, 0.f, 0.f};
};

}  // namespace pathspace
