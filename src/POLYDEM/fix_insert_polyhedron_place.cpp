/* ----------------------------------------------------------------------
   POLYDEM - fix insert/polyhedron: where particles go. The region (its box
   as it moves, its volume, positions drawn in it, containment of a posed
   body), the particles near it gathered alike on every rank, one
   insertion placing particles one after the other, and their creation on
   the owning ranks. Keywords, schedule and restart: fix_insert_polyhedron.cpp
------------------------------------------------------------------------- */

#include "fix_insert_polyhedron.h"

#include "accelerator_kokkos.h"
#include "atom.h"
#include "atom_masks.h"
#include "atom_vec.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "group.h"
#include "math_const.h"
#include "modify.h"
#include "pair.h"
#include "poly_shape_library.h"
#include "polydem_lammps_compat.h"
#include "polydem_parse.h"
#include "polydem_rigid.h"
#include "polydem_shape_template.h"
#include "region.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;
using MathConst::MY_PI;

namespace {
// Region::forward_transform is protected; a pointer to it is formed through
// a derived class (where the name is accessible) and called on the region.
struct RegionMotion : public Region {
  static void forward(Region *r, double &x, double &y, double &z)
  {
    void (Region::*f)(double &, double &, double &) = &RegionMotion::forward_transform;
    (r->*f)(x, y, z);
  }
};

constexpr int REGION_TRIES = 1000;    // position draws per attempt before giving up

// radical-inverse (van der Corput) of i in base b: the Halton sequence
double halton(unsigned i, unsigned b)
{
  double f = 1.0, r = 0.0;
  while (i > 0) {
    f /= b;
    r += f * (i % b);
    i /= b;
  }
  return r;
}

}    // namespace

/* ----------------------------------------------------------------------
   bounding box of the region where it is now (a moving region's box
   follows its motion: the box of the moved corners)
------------------------------------------------------------------------- */

void FixInsertPolyhedron::region_bbox(double *lo, double *hi)
{
  const double elo[3] = {region->extent_xlo, region->extent_ylo, region->extent_zlo};
  const double ehi[3] = {region->extent_xhi, region->extent_yhi, region->extent_zhi};
  // LAMMPS after 4 Feb 2025 moves the extent of a moving block, cone,
  // cylinder, ellipsoid, prism or sphere itself (their bbox_update, run by
  // prematch, which every caller runs first); other styles' stays put
  bool extent_moves = false;
#if POLYDEM_LAMMPS_REGION_EXTENT_MOVES
  for (const char *st : {"block", "cone", "cylinder", "ellipsoid", "prism", "sphere"})
    extent_moves = extent_moves || strcmp(region->style, st) == 0;
#endif
  if (!region->dynamic || extent_moves) {
    for (int k = 0; k < 3; k++) {
      lo[k] = elo[k];
      hi[k] = ehi[k];
    }
  } else {
    for (int k = 0; k < 3; k++) {
      lo[k] = 1e300;
      hi[k] = -1e300;
    }
    for (int c = 0; c < 8; c++) {
      double p[3] = {(c & 1) ? ehi[0] : elo[0], (c & 2) ? ehi[1] : elo[1],
                     (c & 4) ? ehi[2] : elo[2]};
      RegionMotion::forward(region, p[0], p[1], p[2]);
      for (int k = 0; k < 3; k++) {
        lo[k] = std::min(lo[k], p[k]);
        hi[k] = std::max(hi[k], p[k]);
      }
    }
  }
  // only the part inside the simulation box can take particles (a block
  // with INF bounds, a region reaching out of the box)
  for (int k = 0; k < 3; k++) {
    lo[k] = std::max(lo[k], domain->boxlo[k]);
    hi[k] = std::min(hi[k], domain->boxhi[k]);
  }
}

/* ----------------------------------------------------------------------
   region volume (within the simulation box): its box times the fraction
   of 2^18 Halton points inside (exact for a block; relative error ~1e-4
   for smooth boundaries), the same on every rank
------------------------------------------------------------------------- */

double FixInsertPolyhedron::estimate_region_volume()
{
  double lo[3], hi[3];
  region_bbox(lo, hi);
  const double ext[3] = {hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]};
  if (!(ext[0] > 0.0 && ext[1] > 0.0 && ext[2] > 0.0)) return 0.0;
  const unsigned n = 1u << 18;
  unsigned hit = 0;
  for (unsigned i = 1; i <= n; i++)
    hit += region->match(lo[0] + ext[0] * halton(i, 2), lo[1] + ext[1] * halton(i, 3),
                         lo[2] + ext[2] * halton(i, 5))
        ? 1
        : 0;
  return ext[0] * ext[1] * ext[2] * hit / n;
}

/* ---------------------------------------------------------------------- */

polydem::InsertBody<double> FixInsertPolyhedron::body_of(int ishape, double s, const double *x,
                                                         const polydem::Quat<double> &q) const
{
  const auto &t = avec->shape(ishape);
  polydem::InsertBody<double> b;
  b.x = polydem::make_vec3(x[0], x[1], x[2]);
  b.R = polydem::quat_to_mat(q);
  b.s = s;
  b.radius = t.radius() * s;
  if (t.is_ellipsoid()) {
    const auto &a = t.semi_axes();
    b.view = nullptr;
    b.ax = polydem::make_vec3(a[0] * s, a[1] * s, a[2] * s);
    b.inradius = inradius[ishape] * s;
  } else {
    b.view = &views[ishape];
    b.ax = polydem::make_vec3(0.0, 0.0, 0.0);
    b.inradius = inradius[ishape] * s;
  }
  return b;
}

void FixInsertPolyhedron::bodies_of(int ishape, double s, const double *x,
                                    const polydem::Quat<double> &q,
                                    std::vector<polydem::InsertBody<double>> &out,
                                    std::vector<polydem::Quat<double>> *qs) const
{
  out.clear();
  if (qs) qs->clear();
  const auto &t = avec->shape(ishape);
  if (!t.is_composite()) {
    out.push_back(body_of(ishape, s, x, q));
    if (qs) qs->push_back(q);
    return;
  }
  // each part: its template at x + s R x_k, turned by R R_k (polydem_contact_pipeline.h)
  const auto &v = views[ishape];
  polydem::PosedShape<double> whole;
  whole.view = &v;
  whole.x = polydem::make_vec3(x[0], x[1], x[2]);
  whole.R = polydem::quat_to_mat(q);
  whole.s = s;
  for (int k = 0; k < t.nparts(); k++) {
    const auto pp = polydem::posed_part(whole, k);
    const auto &pt = t.part_shape(k);
    polydem::InsertBody<double> b;
    b.x = pp.x;
    b.R = pp.R;
    b.s = s;
    b.radius = pt.radius() * s;
    b.inradius = pt.inradius() * s;
    if (pt.is_ellipsoid()) {
      const auto &a = pt.semi_axes();
      b.view = nullptr;
      b.ax = polydem::make_vec3(a[0] * s, a[1] * s, a[2] * s);
    } else {
      b.view = v.parts[k].view;
      b.ax = polydem::make_vec3(0.0, 0.0, 0.0);
    }
    out.push_back(b);
    const double *pq = v.parts[k].q;
    if (qs) qs->push_back(polydem::qmul(q, polydem::make_quat(pq[0], pq[1], pq[2], pq[3])));
  }
}

// kernel views and inscribed radii (unit scale) of every template: for a
// polyhedron the nearest face plane, for an ellipsoid its smallest semi-axis
void FixInsertPolyhedron::refresh_views()
{
  views.resize(avec->ntemplates());
  inradius.resize(avec->ntemplates());
  for (int i = 0; i < avec->ntemplates(); i++) {
    const auto &t = avec->shape(i);
    views[i] = t.view();
    inradius[i] = t.inradius();
  }
}

/* ----------------------------------------------------------------------
   region containment of a posed body of a particle with centroid xc: the
   centroid in the region; with all yes every vertex of a polyhedron inside
   (exact for a convex region), an ellipsoid's bounding sphere inside
------------------------------------------------------------------------- */

bool FixInsertPolyhedron::region_contains(const polydem::InsertBody<double> &b, const double *xc)
{
  const polydem::ShapeView<double> *v = b.view;
  if (!region->match(xc[0], xc[1], xc[2])) return false;
  if (!allin) return true;
  if (!v) return region->surface(b.x.x, b.x.y, b.x.z, b.radius) == 0;
  for (int i = 0; i < v->nverts; i++) {
    // clang-format off
    const auto p = b.x + b.s * polydem::matvec(b.R, polydem::make_vec3(v->verts[3 * i],
                                                                      v->verts[3 * i + 1],
                                                                      v->verts[3 * i + 2]));
    // clang-format on
    if (!region->match(p.x, p.y, p.z)) return false;
  }
  return true;
}

/* ----------------------------------------------------------------------
   every rank gathers the particles (and periodic images) that can touch a
   candidate in the region's box [lo, hi]: the same list, in tag order, on
   every rank. vol_in_region: their volume with the centroid in the region
------------------------------------------------------------------------- */

std::vector<polydem::InsertBody<double>>
FixInsertPolyhedron::gather(const double *lo, const double *hi, double rcand, double &vol_in_region)
{
  // per row: tag, image code, shape, scale, x (3), q (4)
  constexpr int W = 11;
  const int nlocal = atom->nlocal;
  double **x = atom->x, **quat = atom->quat;
  double *radius = atom->radius, *pscale = atom->pscale;
  int *pshape = atom->pshape;
  tagint *tag = atom->tag;
  const double *prd = domain->prd;
  const int *per = domain->periodicity;
  std::vector<double> mine;
  for (int i = 0; i < nlocal; i++) {
    const double reach = rcand + radius[i] + gap;
    for (int ix = -per[0]; ix <= per[0]; ix++)
      for (int iy = -per[1]; iy <= per[1]; iy++)
        for (int iz = -per[2]; iz <= per[2]; iz++) {
          const double p[3] = {x[i][0] + ix * prd[0], x[i][1] + iy * prd[1], x[i][2] + iz * prd[2]};
          bool in = true;
          for (int k = 0; k < 3; k++) in = in && p[k] > lo[k] - reach && p[k] < hi[k] + reach;
          if (!in) continue;
          const double img = (ix + 1) * 9 + (iy + 1) * 3 + (iz + 1);
          const double row[W] = {
              (double) tag[i], img,        (double) pshape[i], pscale[i], p[0], p[1], p[2],
              quat[i][0],      quat[i][1], quat[i][2],         quat[i][3]};
          mine.insert(mine.end(), row, row + W);
        }
  }
  int nmine = (int) mine.size();
  std::vector<int> counts(comm->nprocs), displs(comm->nprocs);
  MPI_Allgather(&nmine, 1, MPI_INT, counts.data(), 1, MPI_INT, world);
  bigint total = 0;
  for (int p = 0; p < comm->nprocs; p++) {
    displs[p] = (int) total;
    total += counts[p];
  }
  if (total > MAXSMALLINT)
    error->all(FLERR, "fix insert/polyhedron: too many particles near the region");
  std::vector<double> all(total);
  MPI_Allgatherv(mine.data(), nmine, MPI_DOUBLE, all.data(), counts.data(), displs.data(),
                 MPI_DOUBLE, world);
  const int n = (int) (total / W);
  std::vector<int> order(n);
  for (int i = 0; i < n; i++) order[i] = i;
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    const double *ra = &all[(size_t) W * a], *rb = &all[(size_t) W * b];
    return ra[0] != rb[0] ? ra[0] < rb[0] : ra[1] < rb[1];
  });
  std::vector<polydem::InsertBody<double>> bodies, parts;
  vol_in_region = 0.0;
  for (int j = 0; j < n; j++) {
    const double *r = &all[(size_t) W * order[j]];
    const int ishape = (int) r[2];
    const auto q = polydem::make_quat(r[7], r[8], r[9], r[10]);
    bodies_of(ishape, r[3], r + 4, q, parts);
    bodies.insert(bodies.end(), parts.begin(), parts.end());
    if (r[1] == 13.0 && region->match(r[4], r[5], r[6]))
      vol_in_region += avec->shape(ishape).volume() * r[3] * r[3] * r[3];
  }
  return bodies;
}

// add an accepted candidate to the grid, with its periodic images that reach it
void FixInsertPolyhedron::grid_add(const polydem::InsertBody<double> &b)
{
  const double *prd = domain->prd;
  const int *per = domain->periodicity;
  for (int ix = -per[0]; ix <= per[0]; ix++)
    for (int iy = -per[1]; iy <= per[1]; iy++)
      for (int iz = -per[2]; iz <= per[2]; iz++) {
        polydem::InsertBody<double> e = b;
        e.x = b.x + polydem::make_vec3(ix * prd[0], iy * prd[1], iz * prd[2]);
        if ((ix || iy || iz) && !grid.contains(e.x)) continue;
        grid.add(e);
      }
}

/* ---------------------------------------------------------------------- */

polydem::Quat<double> FixInsertPolyhedron::draw_orientation(int ishape)
{
  if (orientstyle == ORIENT_RANDOM) return polydem::random_quat(rng);
  // the template as written in its file, turned about the lab axis
  const auto axis = polydem::make_vec3(oaxis[0], oaxis[1], oaxis[2]);
  const double theta = orientstyle == ORIENT_FIXED ? otheta : 2.0 * MY_PI * rng.uniform();
  return polydem::qnormalize(
      polydem::qmul(polydem::axis_quat(axis, theta), avec->shape(ishape).input_orientation()));
}

void FixInsertPolyhedron::draw_range(const double *lo, const double *hi, double *out)
{
  for (int k = 0; k < 3; k++)
    out[k] = lo[k] == hi[k] ? lo[k] : lo[k] + (hi[k] - lo[k]) * rng.uniform();
}

// a point uniform in the region (within the box), from its current box
bool FixInsertPolyhedron::sample_in_region(double *x)
{
  for (int t = 0; t < REGION_TRIES; t++) {
    for (int k = 0; k < 3; k++) x[k] = slo[k] + (shi[k] - slo[k]) * rng.uniform();
    if (region->match(x[0], x[1], x[2])) return true;
  }
  return false;
}

// mode pack: the first progress line (particles), and at least one line this often (s)
static constexpr bigint PROGRESS_FIRST = 10000;
static constexpr double PROGRESS_SECONDS = 60.0;

/* ----------------------------------------------------------------------
   one insertion: particles are drawn (kind, scale) and placed one after
   the other, each with up to `attempts` poses, until nmax particles (< 0:
   no limit), the mass mstop or the solid fraction phistop (<= 0: none) is
   reached, or a particle finds no place. Same sequence on every rank.
------------------------------------------------------------------------- */

int FixInsertPolyhedron::insert(bigint nmax, double mstop, double phistop)
{
  const double t0 = MPI_Wtime();
  if (lmp->kokkos) atomKK->sync(Host, ALL_MASK);
  // ghosts are overwritten by new atoms (as in Comm::exchange)
  if (atom->map_style != Atom::MAP_NONE) atom->map_clear();
  atom->nghost = 0;
  atom->avec->clear_bonus();

  region->prematch();
  refresh_views();
  double lo[3], hi[3];
  region_bbox(lo, hi);
  for (int k = 0; k < 3; k++) {
    slo[k] = lo[k];
    shi[k] = hi[k];
  }
  const double rcand = rmax_insert;
  double vol = 0.0;
  auto bodies = gather(lo, hi, rcand, vol);
  double rmax = rcand;
  for (const auto &b : bodies) rmax = std::max(rmax, b.radius);
  grid.setup(lo, hi, rcand + rmax + gap, std::move(bodies));
  auto inside = [&](double x, double y, double z) {
    return region->match(x, y, z) != 0;
  };
  const bool voids = mode == MODE_PACK;
  if (voids) {
    double rin = 1e300;
    for (const auto &k : kinds) rin = std::min(rin, inradius[k.ishape] * k.scale.min());
    auto surface = [&](double x, double y, double z, double cut) {
      const int nc = region->surface(x, y, z, cut);
      double d = 1e300;
      for (int m = 0; m < nc; m++) d = std::min(d, region->contact[m].r);
      return d;
    };
    space.setup(lo, hi, rin, allin, inside, surface, grid);
  }

  const double *boxlo = domain->boxlo, *boxhi = domain->boxhi;
  const int *per = domain->periodicity;
  std::vector<Placed> placed;
  double mass = massinserted;
  bool failed = false;
  int miss_run = 0;
  const double goal = voids ? pack_estimate(nmax, mstop - mass, phistop, vol) : 0.0;
  bigint next_progress = PROGRESS_FIRST;
  double last_progress = MPI_Wtime();
  while (nmax < 0 || (bigint) placed.size() < nmax) {
    if (voids) {
      // progress of a long fill: at 1e4, 2e4, 5e4, 1e5, ... particles, and
      // at least every PROGRESS_SECONDS (rank 0's clock: printing only)
      const bigint n = (bigint) placed.size();
      const bool timed = comm->me == 0 && MPI_Wtime() - last_progress > PROGRESS_SECONDS;
      if (n >= next_progress || timed) {
        if (comm->me == 0)
          utils::logmesg(lmp,
                         "fix insert/polyhedron {}: packed {} of about {:.4g} particle(s), solid "
                         "fraction {:.4g}, {} attempts, {:.1f} s\n",
                         id, n, goal, vol / region_volume, nattempts, MPI_Wtime() - t0);
        last_progress = MPI_Wtime();
        while (next_progress <= n) next_progress = next_milestone(next_progress);
      }
    }
    // a mass target is met to within half a particle: insert while that
    // brings the total closer to it (on the mixture's mean mass)
    if (mstop > 0.0 && mass + 0.5 * mean_mass >= mstop) break;
    if (phistop > 0.0 && vol >= phistop * region_volume) break;
    // the particle: kind and scale, kept over its attempts
    const double u = rng.uniform();
    int ik = 0;
    while (ik < (int) kinds.size() - 1 && u >= kinds[ik].pnum) ik++;
    const Kind &kd = kinds[ik];
    const double s = kd.scale.draw(rng);
    const auto &t = avec->shape(kd.ishape);
    bool ok = false;
    Placed p;
    std::vector<polydem::InsertBody<double>> bs;    // its convex bodies (a composite's parts)
    std::vector<polydem::Quat<double>> qs;           // and their orientations
    for (int a = 0; a < attempts && !ok; a++) {
      nattempts++;
      if (voids ? !space.sample(rng, inside, p.x) : !sample_in_region(p.x)) {
        if (voids && space.saturated()) break;
        continue;
      }
      const auto q = draw_orientation(kd.ishape);
      bodies_of(kd.ishape, s, p.x, q, bs, &qs);
      bool inbox = true;
      for (int k = 0; k < 3; k++)
        inbox = inbox && (per[k] || (p.x[k] >= boxlo[k] && p.x[k] < boxhi[k]));
      if (!inbox) continue;
      bool inside_all = true;
      for (const auto &b : bs) inside_all = inside_all && region_contains(b, p.x);
      if (!inside_all) continue;
      bool apart = true;
      for (const auto &b : bs) apart = apart && grid.apart(b, gap);
      if (!apart) {
        if (voids) space.failed(grid);
        continue;
      }
      ok = true;
      for (size_t k = 0; k < bs.size(); k++)
        for (auto w : walls) ok = ok && w->insertion_clear(bs[k], qs[k], gap);
      p.q[0] = q.w;
      p.q[1] = q.x;
      p.q[2] = q.y;
      p.q[3] = q.z;
    }
    if (!ok) {
      nfailed++;
      // mode rate: the rest waits for the next insertion; mode pack: stop
      // after `misses` particles in a row found no place, or at saturation
      if (!voids || ++miss_run >= misses || space.saturated()) {
        failed = true;
        break;
      }
      continue;
    }
    miss_run = 0;
    p.kind = ik;
    p.s = s;
    p.rho = kd.density;
    draw_range(vlo, vhi, p.v);
    draw_range(wlo, whi, p.w);
    placed.push_back(p);
    for (const auto &b : bs) {
      grid_add(b);
      if (voids) space.kill(b);
    }
    const double v = t.volume() * s * s * s;
    vol += v;
    volinserted += v;
    mass += kd.density * v;
  }
  massinserted = mass;
  create(placed);
  if (lmp->kokkos) atomKK->modified(Host, ALL_MASK);
  last_phi = vol / region_volume;
  time_run += MPI_Wtime() - t0;
  return failed ? -(int) placed.size() - 1 : (int) placed.size();
}

/* ----------------------------------------------------------------------
   mode pack: the particles still to place to reach the nearest of the
   limits (count nmax >= 0, mass dm > 0 on the mean mass, solid fraction
   phistop > 0 of the region holding the volume vol on the mean volume),
   printed before the fill; an error if atom IDs cannot count that far
------------------------------------------------------------------------- */

double FixInsertPolyhedron::pack_estimate(bigint nmax, double dm, double phistop, double vol)
{
  const std::string me = "fix insert/polyhedron";
  double est = 1e300;
  std::string how;
  auto limit = [&](double n, const std::string &what) {
    n = std::max(0.0, n);
    est = std::min(est, n);
    how += fmt::format("{}{}: {:.4g}", how.empty() ? "" : "; ", what, n);
  };
  if (nmax >= 0) limit((double) nmax, fmt::format("N {}", ntotal));
  if (masstotal > 0.0) limit(std::ceil(dm / mean_mass), fmt::format("mass/total {}", masstotal));
  if (phistop > 0.0)
    limit(std::ceil((phistop * region_volume - vol) / mean_volume),
          fmt::format("fraction {}", phistop));
  if (comm->me == 0)
    utils::logmesg(lmp,
                   "fix insert/polyhedron {}: mode pack into region '{}' aims at about {:.4g} "
                   "particle(s) ({}; mean particle volume {:.4g})\n",
                   id, idregion, est, how, mean_volume);
  if (est > (double) MAXTAGINT)
    error->all(FLERR,
               "{}: mode pack into region '{}' needs about {:.4g} particles ({}), more than "
               "atom IDs can number ({}): lower the fraction or raise the scale",
               me, idregion, est, how, MAXTAGINT);
  return est;
}

// 1e4, 2e4, 5e4, 1e5, 2e5, ...: the next of the 1-2-5 series after n
bigint FixInsertPolyhedron::next_milestone(bigint n)
{
  bigint decade = 1;
  while (decade * 10 <= n) decade *= 10;
  const bigint lead = n / decade;
  return lead < 2 ? 2 * decade : (lead < 5 ? 5 * decade : 10 * decade);
}

/* ----------------------------------------------------------------------
   the rank owning each placed particle creates it; IDs follow the order
   of placement after the largest existing ID
------------------------------------------------------------------------- */

void FixInsertPolyhedron::create(const std::vector<Placed> &placed)
{
  tagint maxtag = 0;
  for (int i = 0; i < atom->nlocal; i++) maxtag = std::max(maxtag, atom->tag[i]);
  tagint maxtag_all;
  MPI_Allreduce(&maxtag, &maxtag_all, 1, MPI_LMP_TAGINT, MPI_MAX, world);
  if ((bigint) maxtag_all + (bigint) placed.size() >= MAXTAGINT)
    error->all(FLERR, "fix insert/polyhedron: new atom IDs exceed the largest allowed ID");

  const double *sublo = domain->sublo, *subhi = domain->subhi;
  for (size_t k = 0; k < placed.size(); k++) {
    const Placed &p = placed[k];
    double x[3] = {p.x[0], p.x[1], p.x[2]};
    imageint image = ((imageint) IMGMAX << IMG2BITS) | ((imageint) IMGMAX << IMGBITS) | IMGMAX;
    domain->remap(x, image);
    bool mine = true;
    for (int d = 0; d < 3; d++) mine = mine && x[d] >= sublo[d] && x[d] < subhi[d];
    if (!mine) continue;
    const int ishape = kinds[p.kind].ishape;
    const auto &t = avec->shape(ishape);
    atom->avec->create_atom(itype, x);
    const int n = atom->nlocal - 1;
    atom->tag[n] = maxtag_all + (tagint) k + 1;
    atom->mask[n] = 1 | groupbit;
    atom->image[n] = image;
    for (int d = 0; d < 3; d++) atom->v[n][d] = p.v[d];
    atom->pshape[n] = ishape;
    atom->pscale[n] = p.s;
    atom->rmass[n] = p.rho * t.volume() * p.s * p.s * p.s;
    atom->radius[n] = t.radius() * p.s;
    for (int d = 0; d < 4; d++) atom->quat[n][d] = p.q[d];
    double inertia[3];
    avec->inertia(n, inertia);
    polydem::angmom_from_omega(inertia, p.w, atom->quat[n], atom->angmom[n]);
    polydem::omega_from_angmom(inertia, atom->angmom[n], atom->quat[n], atom->omega[n]);
    modify->create_attribute(n);
  }
  ninserted += (bigint) placed.size();
  atom->natoms += (bigint) placed.size();
  if (atom->natoms < 0) error->all(FLERR, "fix insert/polyhedron: too many atoms");
  if (atom->map_style != Atom::MAP_NONE) {
    atom->map_init();
    atom->map_set();
  }
}

