/* -*- c++ -*- ----------------------------------------------------------
   POLYDEM - the space of fix insert/polyhedron's candidates (host code, no
   LAMMPS includes): the grid of the particles a candidate is tested against,
   and the void cells of random sequential addition. The region is reached
   through callbacks, so the tests can drive this with any shape.
------------------------------------------------------------------------- */

#ifndef POLYDEM_INSERT_SPACE_H
#define POLYDEM_INSERT_SPACE_H

#include "polydem_insert.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace polydem {

// The edge of cubic cells over the box [lo, hi]: h, enlarged by factors of
// 1.25 until at most maxcells cells cover the box. No bound on the number
// of enlargements: a particle 1e-12 of the box (a cell count of 1e36) needs
// some 200 of them, and the loop ends once one cell spans the box.
inline double capped_edge(const double *lo, const double *hi, double h, double maxcells)
{
  double ext = 0.0;
  for (int k = 0; k < 3; k++) ext = std::max(ext, hi[k] - lo[k]);
  if (!(h > 0.0) || !std::isfinite(h)) h = ext > 0.0 ? ext : 1.0;
  for (;;) {
    double ncell = 1.0;
    for (int k = 0; k < 3; k++) ncell *= std::max(1.0, std::ceil((hi[k] - lo[k]) / h));
    if (ncell <= maxcells || !(h < ext)) return h;
    h *= 1.25;
  }
}

// The particles a candidate is tested against, binned in cells of edge >=
// reach (the largest bounding radius of a candidate plus the largest present
// plus the gap), so a candidate's neighbours lie in the 27 cells around it.
class InsertGrid {
 public:
  static constexpr int MAXCELLS = 1 << 22;

  // cells over [lo - reach, hi + reach] for the bodies given
  void setup(const double *lo, const double *hi, double reach,
             std::vector<InsertBody<double>> &&bodies)
  {
    bodies_ = std::move(bodies);
    h_ = reach;
    for (int k = 0; k < 3; k++) {
      lo_[k] = lo[k] - reach;
      hi_[k] = hi[k] + reach;
    }
    h_ = capped_edge(lo_, hi_, reach, MAXCELLS);
    for (int k = 0; k < 3; k++) n_[k] = std::max(1, (int) std::ceil((hi_[k] - lo_[k]) / h_));
    head_.assign((size_t) n_[0] * n_[1] * n_[2], -1);
    next_.clear();
    for (int i = 0; i < (int) bodies_.size(); i++) link(i);
  }

  bool contains(const Vec3<double> &x) const
  {
    for (int k = 0; k < 3; k++)
      if (!(x[k] > lo_[k] && x[k] < hi_[k])) return false;
    return true;
  }

  void add(const InsertBody<double> &b)
  {
    bodies_.push_back(b);
    link((int) bodies_.size() - 1);
  }

  const std::vector<InsertBody<double>> &bodies() const { return bodies_; }

  // f(body) for every body in the 27 cells around x
  template <typename F> void for_each_near(const Vec3<double> &x, F &&f) const
  {
    int c[3];
    cell_of(x, c);
    for (int k = std::max(0, c[2] - 1); k <= std::min(n_[2] - 1, c[2] + 1); k++)
      for (int j = std::max(0, c[1] - 1); j <= std::min(n_[1] - 1, c[1] + 1); j++)
        for (int i = std::max(0, c[0] - 1); i <= std::min(n_[0] - 1, c[0] + 1); i++)
          for (int e = head_[(k * n_[1] + j) * n_[0] + i]; e >= 0; e = next_[e])
            if (!f(bodies_[e])) return;
  }

  // b certified apart by more than gap from every body: the bounding and
  // inscribed balls of all neighbours first (cheap), then the exact test,
  // nearest first (the likeliest overlap)
  bool apart(const InsertBody<double> &b, double gap)
  {
    near_.clear();
    bool overlap = false;
    for_each_near(b.x, [&](const InsertBody<double> &o) {
      const double dd = norm2(b.x - o.x);
      const double far = b.radius + o.radius + gap, in = b.inradius + o.inradius;
      if (dd > far * far) return true;
      if (dd < in * in) return !(overlap = true);
      near_.emplace_back(dd, &o);
      return true;
    });
    if (overlap) return false;
    std::sort(near_.begin(), near_.end(),
              [](const std::pair<double, const InsertBody<double> *> &a,
                 const std::pair<double, const InsertBody<double> *> &c) {
                return a.first < c.first;
              });
    for (const auto &n : near_)
      if (!bodies_apart(b, *n.second, gap)) return false;
    return true;
  }

 private:
  std::vector<InsertBody<double>> bodies_;
  std::vector<int> head_, next_;
  std::vector<std::pair<double, const InsertBody<double> *>> near_;
  double lo_[3] = {0, 0, 0}, hi_[3] = {0, 0, 0}, h_ = 1.0;
  int n_[3] = {1, 1, 1};

  int cell_of(const Vec3<double> &x, int *c) const
  {
    for (int k = 0; k < 3; k++) {
      const double u = (x[k] - lo_[k]) / h_;
      c[k] = u > 0.0 ? (u < n_[k] ? (int) u : n_[k] - 1) : 0;    // also NaN -> 0
    }
    return (c[2] * n_[1] + c[1]) * n_[0] + c[0];
  }
  void link(int i)
  {
    int c[3];
    const int cell = cell_of(bodies_[i].x, c);
    if ((int) next_.size() <= i) next_.resize(i + 1);
    next_[i] = head_[cell];
    head_[cell] = i;
  }
};

// Void cells of random sequential addition (mode pack): the region's box in
// cells of edge rin/4, rin the smallest inscribed radius of the candidates.
// A cell is dead once each of its points lies within rin of one body: no
// candidate centred there can be apart from it (its inscribed ball would
// overlap the body). Drawing a live cell uniformly, then a point in it, is
// uniform over the live cells, which hold every place a candidate can still
// take: the law of the random sequential addition is unchanged while its
// draws go to the remaining voids (what makes high fractions reachable).
// The distance to a convex body is a convex function, so its largest value
// on a cell is at a corner: 8 corners decide, exactly.
class InsertVoids {
 public:
  static constexpr int MAXCELLS = 1 << 24;
  static constexpr int FAILS = 8;       // failed draws in a live cell before it is checked again
  static constexpr int LEVELS = 2;      // deepest split of that check (4 x 4 x 4 sub-cells)
  static constexpr int TRIES = 1000;    // points drawn outside the region before giving up

  // inside(x, y, z): the region; surface(x, y, z, cut): distance to the
  // region's surface if below cut (else >= cut); allin: the candidates must
  // lie inside the region, so cells within rin of its surface are dead too
  template <typename In, typename Surf>
  void setup(const double *lo, const double *hi, double rin, bool allin, In &&inside,
             Surf &&surface, const InsertGrid &grid)
  {
    rin_ = rin;
    h_ = capped_edge(lo, hi, 0.25 * rin, MAXCELLS);
    for (int k = 0; k < 3; k++) {
      lo_[k] = lo[k];
      n_[k] = std::max(1, (int) std::ceil((hi[k] - lo[k]) / h_));
    }
    const size_t ncell = (size_t) n_[0] * n_[1] * n_[2];
    dead_.assign(ncell, 0);
    fails_.assign(ncell, 0);
    checks_.assign(ncell, 0);
    alive_.clear();
    const double hd = 0.5 * std::sqrt(3.0) * h_;    // half diagonal of a cell
    for (int k = 0; k < n_[2]; k++)
      for (int j = 0; j < n_[1]; j++)
        for (int i = 0; i < n_[0]; i++) {
          const int c = (k * n_[1] + j) * n_[0] + i;
          // cells the region touches at their centre or a corner
          const double cx = lo_[0] + (i + 0.5) * h_, cy = lo_[1] + (j + 0.5) * h_,
                       cz = lo_[2] + (k + 0.5) * h_;
          const bool centre = inside(cx, cy, cz);
          bool in = centre;
          for (int m = 0; m < 8 && !in; m++)
            in = inside(lo_[0] + (i + (m & 1)) * h_, lo_[1] + (j + ((m >> 1) & 1)) * h_,
                        lo_[2] + (k + ((m >> 2) & 1)) * h_);
          // a candidate whose inscribed ball crosses the surface of a convex
          // region has a vertex outside
          if (centre && allin && surface(cx, cy, cz, rin) + hd < rin) in = false;
          if (in)
            alive_.push_back(c);
          else
            dead_[c] = 1;
        }
    for (const auto &b : grid.bodies()) kill(b);
  }

  // kill the cells each of whose points lies within rin of body b
  void kill(const InsertBody<double> &b)
  {
    const double R = b.radius + rin_, rin = b.inradius + rin_;
    int clo[3], chi[3], m[3];
    for (int k = 0; k < 3; k++) {
      clo[k] = std::max(0, (int) std::floor((b.x[k] - R - lo_[k]) / h_));
      chi[k] = std::min(n_[k] - 1, (int) std::floor((b.x[k] + R - lo_[k]) / h_));
      if (chi[k] < clo[k]) return;
      m[k] = chi[k] - clo[k] + 2;    // corners per direction
    }
    corner_.assign((size_t) m[0] * m[1] * m[2], 0);
    for (int k = 0; k < m[2]; k++)
      for (int j = 0; j < m[1]; j++)
        for (int i = 0; i < m[0]; i++) {
          const auto p = make_vec3(lo_[0] + (clo[0] + i) * h_, lo_[1] + (clo[1] + j) * h_,
                                   lo_[2] + (clo[2] + k) * h_);
          const double d2 = norm2(p - b.x);
          corner_[((size_t) k * m[1] + j) * m[0] + i] = d2 <= rin * rin ||
              (d2 <= R * R && point_within(b, p, rin_));
        }
    for (int k = clo[2]; k <= chi[2]; k++)
      for (int j = clo[1]; j <= chi[1]; j++)
        for (int i = clo[0]; i <= chi[0]; i++) {
          const int c = (k * n_[1] + j) * n_[0] + i;
          if (dead_[c]) continue;
          bool all = true;
          for (int q = 0; q < 8 && all; q++)
            all = corner_[((size_t) (k - clo[2] + ((q >> 2) & 1)) * m[1] +
                           (j - clo[1] + ((q >> 1) & 1))) *
                              m[0] +
                          (i - clo[0] + (q & 1))];
          if (all) dead_[c] = 1;
        }
  }

  // a point uniform over the live cells that lies in the region; false once
  // no cell is left (saturated) or after TRIES points outside it
  template <typename In> bool sample(InsertRng &rng, In &&inside, double *x)
  {
    for (int t = 0; t < TRIES;) {
      if (alive_.empty()) return false;
      const size_t idx = std::min(alive_.size() - 1, (size_t) (rng.uniform() * alive_.size()));
      const int c = alive_[idx];
      if (dead_[c]) {    // found dead: drop it (no draw of a point)
        alive_[idx] = alive_.back();
        alive_.pop_back();
        continue;
      }
      const int i = c % n_[0], j = (c / n_[0]) % n_[1], k = c / (n_[0] * n_[1]);
      last_ = c;
      x[0] = lo_[0] + (i + rng.uniform()) * h_;
      x[1] = lo_[1] + (j + rng.uniform()) * h_;
      x[2] = lo_[2] + (k + rng.uniform()) * h_;
      if (inside(x[0], x[1], x[2])) return true;
      t++;
    }
    return false;
  }

  bool saturated() const { return alive_.empty(); }

  // is the cell holding x dead (outside the cells: true)
  bool dead_at(const double *x) const
  {
    int c[3];
    for (int k = 0; k < 3; k++) {
      const double u = (x[k] - lo_[k]) / h_;
      if (!(u >= 0.0 && u < n_[k])) return true;
      c[k] = (int) u;
    }
    return dead_[(c[2] * n_[1] + c[1]) * n_[0] + c[0]] != 0;
  }

  // a candidate drawn in the last cell overlapped something: after FAILS
  // such draws the cell is checked again against the bodies together
  void failed(const InsertGrid &grid)
  {
    if (++fails_[last_] < FAILS) return;
    fails_[last_] = 0;
    refine(last_, grid);
  }

 private:
  std::vector<char> dead_, corner_;
  std::vector<unsigned char> fails_, checks_;
  std::vector<int> alive_;
  double lo_[3] = {0, 0, 0}, h_ = 1.0, rin_ = 0.0;
  int n_[3] = {1, 1, 1};
  int last_ = 0;

  // A live cell may be covered by several bodies together (each of its
  // points within rin of one of them) though by none alone: split it into
  // 2^L sub-cells per direction (L = 1, 2 at its first, second check) and
  // kill it if each sub-cell has its 8 corners within rin of one body.
  void refine(int c, const InsertGrid &grid)
  {
    if (checks_[c] >= LEVELS) return;    // checked to the deepest level: a true void
    const int level = ++checks_[c];
    const int ci = c % n_[0], cj = (c / n_[0]) % n_[1], ck = c / (n_[0] * n_[1]);
    const auto c0 = make_vec3(lo_[0] + ci * h_, lo_[1] + cj * h_, lo_[2] + ck * h_);
    const auto cc = c0 + make_vec3(0.5 * h_, 0.5 * h_, 0.5 * h_);
    const double hd = 0.5 * std::sqrt(3.0) * h_;
    const InsertBody<double> *near[64];    // the bodies whose zone can reach the cell
    int nb = 0;
    bool many = false;
    grid.for_each_near(cc, [&](const InsertBody<double> &o) {
      const double r = o.radius + rin_ + hd;
      if (norm2(o.x - cc) > r * r) return true;
      if (nb == 64) return !(many = true);
      near[nb++] = &o;
      return true;
    });
    if (nb == 0 || many) return;
    const int n = 1 << level, m = n + 1;
    const double h = h_ / n;
    uint64_t cover[(4 + 1) * (4 + 1) * (4 + 1)];
    for (int k = 0; k < m; k++)
      for (int j = 0; j < m; j++)
        for (int i = 0; i < m; i++) {
          const auto p = c0 + make_vec3(i * h, j * h, k * h);
          uint64_t bits = 0;
          for (int b = 0; b < nb; b++) {
            const auto &o = *near[b];
            const double d2 = norm2(p - o.x);
            const double rin = o.inradius + rin_, R = o.radius + rin_;
            if (d2 <= rin * rin || (d2 <= R * R && point_within(o, p, rin_)))
              bits |= (uint64_t) 1 << b;
          }
          cover[(k * m + j) * m + i] = bits;
        }
    for (int k = 0; k < n; k++)
      for (int j = 0; j < n; j++)
        for (int i = 0; i < n; i++) {
          uint64_t all = ~(uint64_t) 0;
          for (int q = 0; q < 8 && all; q++)
            all &= cover[((k + ((q >> 2) & 1)) * m + (j + ((q >> 1) & 1))) * m + (i + (q & 1))];
          if (!all) return;    // a sub-cell may hold a place
        }
    dead_[c] = 1;
  }
};

}    // namespace polydem

#endif
