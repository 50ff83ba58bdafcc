/* ----------------------------------------------------------------------
   POLYDEM - the time-step check of pairs and walls (poly_timestep.h)
------------------------------------------------------------------------- */

#include "poly_timestep.h"

#include "comm.h"
#include "error.h"
#include "lammps.h"
#include "math_const.h"
#include "update.h"
#include "utils.h"

#include <cmath>
#include <mpi.h>

using namespace LAMMPS_NS;
using MathConst::MY_PI;

void TimestepCheck::contact(double m, double kn)
{
  tc = std::fmin(tc, MY_PI * sqrt(m / kn));
}

void TimestepCheck::flat_face(double dt)
{
  if (dt > 0.0) face = std::fmin(face, dt);
}

void TimestepCheck::report(LAMMPS *lmp, const std::string &who, const std::string &what,
                           const std::string &against, double core)
{
  double mine[2] = {tc, face}, all[2];
  MPI_Allreduce(mine, all, 2, MPI_DOUBLE, MPI_MIN, lmp->world);
  tc = all[0];
  face = all[1];
  if (lmp->comm->me != 0) return;
  const double dt = lmp->update->dt;
  if (tc < 1e300) {
    utils::logmesg(lmp, "{}: contact time {:.4g} ({}), timestep {:.4g} = t_c/{:.3g}\n", who, tc,
                   what, dt, tc / dt);
    if (dt > tc / 10.0)
      lmp->error->warning(FLERR, "{}: timestep {:.4g} exceeds t_c/10 = {:.4g} (contact time "
                          "{:.4g}, {}): contacts will be poorly resolved", who, dt, tc / 10.0, tc,
                          what);
  }
  if (face < 1e300) {
    utils::logmesg(lmp, "{}: a face flat on {} in the core (core {}) is stable for timesteps "
                   "below {:.4g}, resolved below about {:.4g}\n", who, against, core, face,
                   face / 20.0);
    if (dt > 0.5 * face)
      lmp->error->warning(FLERR, "{}: timestep {:.4g} exceeds half of {:.4g}, the stability "
                          "limit of a largest face resting flat on {} in the core (stiffness "
                          "5/3 K V0^(-2/3) A^2): flat contacts may stick or gain energy; lower "
                          "the timestep or raise core", who, dt, face, against);
  }
}
