// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LIGGGHTS 3.8: fix tdem/integrate (see fix_tdem_integrate.h and docs/liggghts/fix_tdem_integrate.md).
#include "fix_tdem_integrate.h"
#include "integrators/fix_args.h"
#include "fixes/liggghts/style_maps.h"

#include <mpi.h>

#include <cstdio>
#include <cstring>
#include <map>
#include <string>

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "lammps.h"
#include "memory.h"
#include "modify.h"
#include "update.h"

using namespace LAMMPS_NS;
using namespace FixConst;
namespace ti = tdem::integrators;

namespace {

std::string allowed_schemes() { return ti::scheme_names(" | "); }

std::string fmt_double(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.15g", x);
  return buf;
}

}  // namespace

/* ---------------------------------------------------------------------- */

FixTDEMIntegrate::FixTDEMIntegrate(LAMMPS* lmp, int narg, char** arg)
    : PerAtomRows(lmp, narg, arg),
      scheme_(ti::Scheme::velocity_verlet),
      rotation_(true),
      nhist_t_(0),
      nhist_r_(0),
      off_at_(-1),
      off_ar_(-1),
      off_ht_(1),
      off_hr_(1),
      stride_(1),
      code_(0),
      dt_hist_(0.0),
      restart_mismatch_(false) {
  const std::string where = std::string("fix ") + id + " tdem/integrate";
  if (!atom->radius_flag || !atom->rmass_flag || !atom->omega_flag || !atom->torque_flag)
    error->all(FLERR, (where + " replaces fix nve/sphere and requires the per-atom attributes radius, "
                               "rmass, omega and torque (atom_style granular/sphere); atom_style '" +
                       std::string(atom->atom_style ? atom->atom_style : "?") + "' lacks " +
                       (!atom->radius_flag ? "radius" : !atom->rmass_flag ? "rmass"
                                                    : !atom->omega_flag ? "omega" : "torque"))
                          .c_str());

  ti::FixArgs fa;
  const ti::ArgProblem p = ti::parse_fix_args(narg, arg, 3, fa);
  std::string what;
  switch (p.kind) {
    case ti::ArgProblem::none: break;
    case ti::ArgProblem::scheme_needs_value:
      what = "keyword 'scheme' needs a value; allowed values: " + allowed_schemes();
      break;
    case ti::ArgProblem::scheme_unknown:
      what = "keyword 'scheme' has unknown value '" + p.word + "'; allowed values: " + allowed_schemes();
      break;
    case ti::ArgProblem::rotation_needs_value:
      what = "keyword 'rotation' needs a value; allowed values: yes | no";
      break;
    case ti::ArgProblem::rotation_unknown:
      what = "keyword 'rotation' has unknown value '" + p.word + "'; allowed values: yes | no";
      break;
    case ti::ArgProblem::unknown_keyword:
      what = "unknown keyword '" + p.word + "'; allowed keywords: scheme NAME, rotation yes|no";
      break;
    case ti::ArgProblem::scheme_missing:
      what = "keyword 'scheme' is missing (fix ID group tdem/integrate scheme NAME [rotation yes|no]); allowed "
             "values of scheme: " + allowed_schemes();
      break;
  }
  if (!what.empty()) error->all(FLERR, (where + ": " + what).c_str());
  scheme_ = fa.scheme;
  rotation_ = fa.rotation;

  ti::dispatch(scheme_, [&](auto tag) {
    constexpr ti::Scheme S = decltype(tag)::value;
    nhist_t_ = ti::Kernel<S, true>::history;
    nhist_r_ = rotation_ ? ti::Kernel<S, false>::history : 0;
    return 0;
  });
  int n = 1;
  off_at_ = n;
  n += 3;
  if (rotation_) {
    off_ar_ = n;
    n += 3;
  }
  off_ht_ = n;
  n += nhist_t_;
  off_hr_ = n;
  n += nhist_r_;
  stride_ = n;
  code_ = 2 * static_cast<int>(scheme_) + (rotation_ ? 1 : 0);

  time_integrate = 1;
  create_attribute = 1;
  restart_peratom = 1;
  restart_global = 1;
  dt_hist_ = update->dt;

  if (comm->me == 0) {
    char line[256];
    std::snprintf(line, sizeof line,
                  "fix %s tdem/integrate: scheme %s, rotation %s: %d history doubles (translation %d, "
                  "rotation %d) + 1 flag + %d last-acceleration = %d doubles (%d bytes) per atom\n",
                  id, ti::info(scheme_).name, rotation_ ? "yes" : "no", nhist_t_ + nhist_r_, nhist_t_, nhist_r_,
                  rotation_ ? 6 : 3, stride_, static_cast<int>(stride_ * sizeof(double)));
    if (screen) std::fputs(line, screen);
    if (logfile) std::fputs(line, logfile);
  }

  rows_init(stride_, "tdem/integrate:row");
  restart_head_ = 1;  // the scheme code
  grow_arrays(atom->nmax);
  atom->add_callback(0);
  atom->add_callback(1);
}

FixTDEMIntegrate::~FixTDEMIntegrate() {
  atom->delete_callback(id, 0);
  atom->delete_callback(id, 1);
}

int FixTDEMIntegrate::setmask() {
  int mask = 0;
  mask |= INITIAL_INTEGRATE;
  mask |= FINAL_INTEGRATE;
  return mask;
}

double FixTDEMIntegrate::inertia_factor() const { return domain->dimension == 2 ? 0.5 : 0.4; }

void FixTDEMIntegrate::init() {
  // finite-size spheres only (the angular acceleration divides by r^2), as fix nve/sphere
  if (ti::any_point_particle(world, atom, groupbit))
    error->all(FLERR, (std::string("fix ") + id +
                       " tdem/integrate: every atom of the group needs radius > 0 (extended particles)")
                          .c_str());
}

void FixTDEMIntegrate::restart_all(const char* why) {
  int started = 0, all = 0;
  for (int i = 0; i < atom->nlocal; i++)
    if (rows_[i][0] != 0.0) started++;
  MPI_Allreduce(&started, &all, 1, MPI_INT, MPI_SUM, world);
  if (all > 0 && comm->me == 0)
    error->warning(FLERR, (std::string("fix ") + id + " tdem/integrate: " + why +
                           "; the integration history of every atom is started again")
                              .c_str());
  for (int i = 0; i < atom->nlocal; i++) rows_[i][0] = 0.0;
}

// A new run continues the histories, unless the time step changed since they were built.
void FixTDEMIntegrate::setup(int) {
  if (update->dt != dt_hist_) {
    restart_all(("the time step changed from " + fmt_double(dt_hist_) + " to " + fmt_double(update->dt)).c_str());
    dt_hist_ = update->dt;
  }
}

void FixTDEMIntegrate::reset_dt() { setup(0); }

/* ---------------------------------------------------------------------- */

// Acceleration of atom i (into at) and, with rotation, its angular acceleration (into ar) from
// the present force and torque.
template <bool R>
void FixTDEMIntegrate::accelerations(int i, double ftm2v, double inertia, double* at, double* ar) const {
  const double c = ftm2v / atom->rmass[i];
  for (int k = 0; k < 3; k++) at[k] = atom->f[i][k] * c;
  if (R) {
    const double r = atom->radius[i];
    const double ci = ftm2v / (inertia * atom->rmass[i] * r * r);
    for (int k = 0; k < 3; k++) ar[k] = atom->torque[i][k] * ci;
  }
}

FixTDEMIntegrate::Pass FixTDEMIntegrate::pass() const {
  const int n = igroup == atom->firstgroup ? atom->nfirst : atom->nlocal;
  return {atom->x, atom->v, atom->omega, atom->mask, n, update->dt, force->ftm2v, inertia_factor()};
}

template <ti::Scheme S, bool R> void FixTDEMIntegrate::loop_initial() {
  using KT = ti::Kernel<S, true>;
  using KR = ti::Kernel<S, false>;
  const auto [x, v, omega, mask, nlocal, h, ftm2v, inertia] = pass();
  const int oat = off_at_, oar = off_ar_, oht = off_ht_, ohr = off_hr_;

  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    double* s = rows_[i];
    // the stored acceleration of the last force evaluation (see the header)
    double* at = s + oat;
    double* ar = R ? s + oar : nullptr;
    if (s[0] == 0.0) {  // the first complete force of this atom (or the time step changed): start
      accelerations<R>(i, ftm2v, inertia, at, ar);
      ti::start<S, true>(x[i], v[i], at, s + oht, h);
      if (R) ti::start<S, false>(nullptr, omega[i], ar, s + ohr, h);
      s[0] = 1.0;
    } else if constexpr (S == ti::Scheme::velocity_verlet) {
      // as fix nve/sphere: the force present now (the set-up force at the first step of a run,
      // else the same as the stored one)
      accelerations<R>(i, ftm2v, inertia, at, ar);
    }
    KT::predict(x[i], v[i], at, s + oht, h);
    if (R) KR::predict(nullptr, omega[i], ar, s + ohr, h);
  }
}

template <ti::Scheme S, bool R> void FixTDEMIntegrate::loop_final() {
  using KT = ti::Kernel<S, true>;
  using KR = ti::Kernel<S, false>;
  const auto [x, v, omega, mask, nlocal, h, ftm2v, inertia] = pass();
  const int oat = off_at_, oar = off_ar_, oht = off_ht_, ohr = off_hr_;

  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    double* s = rows_[i];
    if (s[0] == 0.0) continue;  // appeared during this step: started at the next initial_integrate
    // velocity_verlet takes the present force at the next step (as nve/sphere): nothing to keep
    double tmp[6];
    double* at = S == ti::Scheme::velocity_verlet ? tmp : s + oat;
    double* ar = S == ti::Scheme::velocity_verlet ? tmp + 3 : s + oar;
    accelerations<R>(i, ftm2v, inertia, at, ar);
    if (KT::has_correct) KT::correct(x[i], v[i], at, s + oht, h);
    if (R && KR::has_correct) KR::correct(nullptr, omega[i], ar, s + ohr, h);
  }
}

void FixTDEMIntegrate::initial_integrate(int) {
  ti::dispatch(scheme_, [&](auto tag) {
    constexpr ti::Scheme S = decltype(tag)::value;
    if (rotation_)
      loop_initial<S, true>();
    else
      loop_initial<S, false>();
    return 0;
  });
}

void FixTDEMIntegrate::final_integrate() {
  ti::dispatch(scheme_, [&](auto tag) {
    constexpr ti::Scheme S = decltype(tag)::value;
    if (rotation_)
      loop_final<S, true>();
    else
      loop_final<S, false>();
    return 0;
  });
}

double FixTDEMIntegrate::memory_usage() { return rows_memory(); }

/* ---------------------------------------------------------------------- per-atom rows */

int FixTDEMIntegrate::pack_restart(int i, double* buf) {
  const double head = code_;
  return pack_row(i, buf, &head);
}

void FixTDEMIntegrate::unpack_restart(int nlocal, int nth) {
  const double head = code_;
  if (restart_mismatch_) set_arrays(nlocal);
  else unpack_row(nlocal, nth, &head);
}

// global restart record: scheme code, time step of the histories, doubles per atom
void FixTDEMIntegrate::write_restart(FILE* fp) {
  if (comm->me != 0) return;
  const double list[3] = {static_cast<double>(code_), dt_hist_, static_cast<double>(stride_)};
  const int size = sizeof(list);
  fwrite(&size, sizeof(int), 1, fp);
  fwrite(list, sizeof(double), 3, fp);
}

void FixTDEMIntegrate::restart(char* buf) {
  double list[3];
  std::memcpy(list, buf, sizeof list);
  const int stored_code = static_cast<int>(list[0]);
  if (stored_code != code_ || static_cast<int>(list[2]) != stride_) {
    restart_mismatch_ = true;
    if (comm->me == 0) {
      const int s = stored_code / 2;
      const std::string old =
          (s >= 0 && s < static_cast<int>(ti::Scheme::count)) ? ti::info(static_cast<ti::Scheme>(s)).name : "?";
      error->warning(FLERR, (std::string("fix ") + id + " tdem/integrate: the restart file holds the history of "
                             "scheme " + old + " (rotation " + (stored_code % 2 ? "yes" : "no") +
                             "), this fix uses scheme " + ti::info(scheme_).name + " (rotation " +
                             (rotation_ ? "yes" : "no") + "); every atom is started again")
                                .c_str());
    }
    return;
  }
  dt_hist_ = list[1];
}

/* ---------------------------------------------------------------------- registration */

void tdem::liggghts::register_fixes(LAMMPS_NS::LAMMPS* lmp) {
  add_fix_style(lmp, "tdem/integrate", &create_fix<FixTDEMIntegrate>);
}
