// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: fix tdem/integrate (see fix_tdem_integrate.h and docs/lammps/fix_tdem_integrate.md).

#include "fix_tdem_integrate.h"

#include "contact_host.h"
#include "integrators/fix_args.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "update.h"

#include <cstdio>
#include <cstring>
#include <mpi.h>
#include <string>

using namespace LAMMPS_NS;
using namespace FixConst;
namespace ti = tdem::integrators;

namespace {
constexpr double kInertiaSphere = 0.4;  // I = 0.4 m r^2, as fix nve/sphere

std::string allowed_schemes()
{
  return ti::scheme_names(", ");
}
}  // namespace

/* ---------------------------------------------------------------------- */

FixTDEMIntegrate::FixTDEMIntegrate(LAMMPS *lmp, int narg, char **arg) :
    PerAtomRows(lmp, narg, arg), scheme(ti::Scheme::velocity_verlet), rotation(1), nhist_t(0), nhist_r(0),
    stride(1), code(0), dt_hist(0.0), dt_prev(0.0), pending(1), restart_mismatch(0)
{
  const std::string where = std::string("fix ") + id + " tdem/integrate";
  if (!atom->radius_flag || !atom->rmass_flag || !atom->omega_flag ||
      !atom->torque_flag)
    error->all(FLERR, where + " requires atom_style sphere (per-atom radius, rmass, omega, torque); "
                              "the current atom style '" + std::string(atom->atom_style) +
                              "' lacks them");

  ti::FixArgs fa;
  const ti::ArgProblem p = ti::parse_fix_args(narg, arg, 3, fa);
  std::string what;
  switch (p.kind) {
    case ti::ArgProblem::none: break;
    case ti::ArgProblem::scheme_needs_value: what = "keyword scheme needs a value; allowed: " + allowed_schemes(); break;
    case ti::ArgProblem::scheme_unknown: what = "scheme '" + p.word + "' is unknown; allowed: " + allowed_schemes(); break;
    case ti::ArgProblem::rotation_needs_value: what = "keyword rotation needs a value; allowed: yes, no"; break;
    case ti::ArgProblem::rotation_unknown: what = "rotation '" + p.word + "' is unknown; allowed: yes, no"; break;
    case ti::ArgProblem::unknown_keyword:
      what = "unexpected argument '" + p.word + "'; allowed: scheme NAME, rotation yes|no";
      break;
    case ti::ArgProblem::scheme_missing: what = "missing keyword 'scheme NAME'; allowed NAME: " + allowed_schemes(); break;
  }
  if (!what.empty()) error->all(FLERR, where + ": " + what);
  scheme = fa.scheme;
  rotation = fa.rotation ? 1 : 0;
  energy_form_[0] = ti::energy_form(scheme);
  energy_form_[1] = scheme == ti::Scheme::velocity_verlet_sync || scheme == ti::Scheme::velocity_verlet_ab2;

  ti::dispatch(scheme, [&](auto tag) {
    constexpr ti::Scheme S = decltype(tag)::value;
    nhist_t = ti::Kernel<S, true>::history;
    nhist_r = rotation ? ti::Kernel<S, false>::history : 0;
    return 0;
  });
  // the acceleration of the last force evaluation of a run, kept for the first step of the next
  // run (not for velocity_verlet, which uses the set-up force as fix nve/sphere does)
  nlast = scheme == ti::Scheme::velocity_verlet ? 0 : 6;
  olast = 1 + nhist_t + nhist_r;
  stride = olast + nlast;
  code = 2 * static_cast<int>(scheme) + rotation;

  if (comm->me == 0)
    utils::logmesg(lmp, fmt::format("fix {} tdem/integrate: scheme {} ({}), rotation {}: {} doubles of "
                                    "history per atom ({} translation + {} rotation) + 1 flag + {} kept acceleration\n",
                                    id, ti::info(scheme).name, ti::info(scheme).summary,
                                    rotation ? "yes" : "no", nhist_t + nhist_r, nhist_t, nhist_r, nlast));

  time_integrate = 1;
  create_attribute = 1;
  restart_peratom = 1;
  restart_global = 1;
  maxexchange = stride;
  dynamic_group_allow = 0;
  dt_hist = update->dt;
  // the per-atom row is output as f_ID[1] (started flag) ... f_ID[stride] (history)
  peratom_flag = 1;
  size_peratom_cols = stride;
  peratom_freq = 1;

  rows_init(stride, "tdem/integrate:rows");
  restart_head_ = 1;  // the scheme code
  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
}

FixTDEMIntegrate::~FixTDEMIntegrate()
{
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
}

int FixTDEMIntegrate::setmask()
{
  return INITIAL_INTEGRATE | FINAL_INTEGRATE;
}

void FixTDEMIntegrate::init()
{
  // extended particles only (the angular acceleration divides by r^2)
  if (ti::any_point_particle(world, atom, groupbit))
    error->all(FLERR, std::string("fix ") + id +
                          " tdem/integrate: every atom of the group needs radius > 0 (extended particles)");
}

// A change of the time step: every started atom is marked 2 ("re-start from a state carried with
// the step dt_prev"); atoms not started yet keep 0.
void FixTDEMIntegrate::clear_started()
{
  for (int i = 0; i < atom->nlocal; i++)
    if (rows_[i][0] != 0.0) rows_[i][0] = 2.0;
  dt_prev = dt_hist;
  pending = 1;
}

// Start (or re-start) atom i from its current state and acceleration. start() takes the
// synchronous velocity; leapfrog and position_verlet carry v(t - h/2) (the backward difference),
// so on a re-start after a change of the time step it is first brought to t with the old step.
template <ti::Scheme S, bool R>
void FixTDEMIntegrate::start_atom(int i, const double *a, const double *al, double h)
{
  double *s = rows_[i];
  double *vi = atom->v[i];
  double *wi = atom->omega[i];
  if constexpr (S == ti::Scheme::leapfrog || S == ti::Scheme::position_verlet) {
    if (s[0] == 2.0)
      for (int k = 0; k < 3; k++) {
        vi[k] += 0.5 * dt_prev * a[k];
        if (R) wi[k] += 0.5 * dt_prev * al[k];
      }
  }
  ti::start<S, true>(atom->x[i], vi, a, s + 1, h);
  if (R) ti::start<S, false>(nullptr, wi, al, s + 1 + nhist_t, h);
  s[0] = 1.0;
}

// A new run: the histories continue unless the time step changed since they were built (the
// `timestep` command after read_restart does not call reset_dt). Atoms without the flag are
// started at the first initial_integrate, when every fix has added its set-up force.
void FixTDEMIntegrate::setup(int /*vflag*/)
{
  if (update->dt != dt_hist) {
    int nstarted = 0, all = 0;
    for (int i = 0; i < atom->nlocal; i++)
      if (rows_[i][0] == 1.0 || rows_[i][0] == 3.0) nstarted++;
    MPI_Allreduce(&nstarted, &all, 1, MPI_INT, MPI_SUM, world);
    if (all > 0 && comm->me == 0)
      error->warning(FLERR, fmt::format("fix {} tdem/integrate: the time step changed from {} to {}; "
                                        "the integration history of every atom is started again",
                                        id, dt_hist, update->dt));
    clear_started();
    dt_hist = update->dt;
  }
}

void FixTDEMIntegrate::reset_dt()
{
  if (update->dt == dt_hist) return;
  if (comm->me == 0)
    error->warning(FLERR, fmt::format("fix {} tdem/integrate: the time step changed from {} to {}; "
                                      "the integration history of every atom is started again",
                                      id, dt_hist, update->dt));
  clear_started();
  dt_hist = update->dt;
}

/* ---------------------------------------------------------------------- */

template <ti::Scheme S, bool R> void FixTDEMIntegrate::loop_initial()
{
  using KT = ti::Kernel<S, true>;
  using KR = ti::Kernel<S, false>;
  auto [x, v, f, omega, torque, radius, rmass, mask, nlocal] = tdem_lammps::sphere_arrays(atom);
  if (igroup == atom->firstgroup) nlocal = atom->nfirst;
  const double h = update->dt, ftm2v = force->ftm2v;
  const int ot = 1, orr = 1 + nhist_t;

  if constexpr (S == ti::Scheme::velocity_verlet) {
    // Kernel<velocity_verlet> with the products grouped as fix nve/sphere groups them
    // ((h/2 ftm2v / m) F instead of (h/2) (ftm2v F / m)), so that the trajectories are bitwise
    // those of nve/sphere (a 1-ulp difference per step grows chaotically in a granular flow)
    const double dtf = 0.5 * h * ftm2v, dtfrot = dtf / kInertiaSphere;
    for (int i = 0; i < nlocal; i++) {
      if (!(mask[i] & groupbit)) continue;
      const double dtfm = dtf / rmass[i];
      for (int k = 0; k < 3; k++) {
        v[i][k] += dtfm * f[i][k];
        x[i][k] += h * v[i][k];
      }
      if (R) {
        const double dtir = dtfrot / (radius[i] * radius[i] * rmass[i]);
        for (int k = 0; k < 3; k++) omega[i][k] += dtir * torque[i][k];
      }
      rows_[i][0] = 1.0;
    }
    return;
  }

  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    double *s = rows_[i];
    double acc[6];
    accelerations(i, acc);
    const double *a = acc, *al = acc + 3;
    const double *ap = a, *alp = al;
    if (s[0] == 3.0) {  // first step of a run: the last force of the previous run, not the set-up force
      ap = s + olast;
      alp = s + olast + 3;
      s[0] = 1.0;
    } else if (s[0] != 1.0) {
      start_atom<S, R>(i, a, al, h);  // first step, or a new time step
    }
    KT::predict(x[i], v[i], ap, s + ot, h);
    if (R) KR::predict(nullptr, omega[i], alp, s + orr, h);
  }
}

template <ti::Scheme S, bool R> void FixTDEMIntegrate::loop_final()
{
  using KT = ti::Kernel<S, true>;
  using KR = ti::Kernel<S, false>;
  auto [x, v, f, omega, torque, radius, rmass, mask, nlocal] = tdem_lammps::sphere_arrays(atom);
  if (igroup == atom->firstgroup) nlocal = atom->nfirst;
  const double h = update->dt, ftm2v = force->ftm2v;
  const int ot = 1, orr = 1 + nhist_t;

  if constexpr (S == ti::Scheme::velocity_verlet) {  // as in loop_initial
    const double dtf = 0.5 * h * ftm2v, dtfrot = dtf / kInertiaSphere;
    for (int i = 0; i < nlocal; i++) {
      if (!(mask[i] & groupbit)) continue;
      const double dtfm = dtf / rmass[i];
      for (int k = 0; k < 3; k++) v[i][k] += dtfm * f[i][k];
      if (R) {
        const double dtir = dtfrot / (radius[i] * radius[i] * rmass[i]);
        for (int k = 0; k < 3; k++) omega[i][k] += dtir * torque[i][k];
      }
      rows_[i][0] = 1.0;
    }
    return;
  }

  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    double *s = rows_[i];
    if (!KT::has_correct && s[0] == 1.0) continue;
    double acc[6];
    accelerations(i, acc);
    const double *a = acc, *al = acc + 3;
    if (s[0] != 1.0) {  // appeared during this step: its first force, start it (no correction)
      start_atom<S, R>(i, a, al, h);
      continue;
    }
    if constexpr (KT::has_correct) {
      KT::correct(x[i], v[i], a, s + ot, h);
      if (R) KR::correct(nullptr, omega[i], al, s + orr, h);
    }
  }
}

// The acceleration (out[0..2]) and angular acceleration (out[3..5], 0 with rotation no) of atom i
// from its present force and torque.
void FixTDEMIntegrate::accelerations(int i, double *out) const
{
  const double c = force->ftm2v / atom->rmass[i];
  const double r = atom->radius[i];
  const double ci = force->ftm2v / (kInertiaSphere * atom->rmass[i] * r * r);
  for (int k = 0; k < 3; k++) {
    out[k] = atom->f[i][k] * c;
    out[3 + k] = rotation ? atom->torque[i][k] * ci : 0.0;
  }
}

// End of a run: keep the last force of every started atom for the first step of the next run.
// The set-up force of the next run is evaluated at the corrected state (and, for some styles,
// with the contact history of the end of the run), not where the scheme evaluated it, so using
// it would make `run N` + `run M` differ from `run N+M` for every scheme with a corrector.
void FixTDEMIntegrate::post_run()
{
  if (!nlast) return;
  const int *mask = atom->mask;
  for (int i = 0; i < atom->nlocal; i++)
    if ((mask[i] & groupbit) && rows_[i][0] == 1.0) {
      accelerations(i, rows_[i] + olast);
      rows_[i][0] = 3.0;
    }
}

void FixTDEMIntegrate::initial_integrate(int /*vflag*/)
{
  ti::dispatch(scheme, [&](auto tag) {
    constexpr ti::Scheme S = decltype(tag)::value;
    if (rotation) loop_initial<S, true>();
    else loop_initial<S, false>();
    return 0;
  });
}

void FixTDEMIntegrate::final_integrate()
{
  // one-step schemes without a corrector loop only when an atom may need its start
  if (!ti::has_correct(scheme) && !pending) return;
  ti::dispatch(scheme, [&](auto tag) {
    constexpr ti::Scheme S = decltype(tag)::value;
    if (rotation) loop_final<S, true>();
    else loop_final<S, false>();
    return 0;
  });
  pending = 0;
}

double FixTDEMIntegrate::memory_usage()
{
  return rows_memory();
}

/* ---------------------------------------------------------------------- per-atom arrays */

void FixTDEMIntegrate::set_arrays(int i)
{
  // a new atom (create_atoms, read_data, fix pour, deposit ...): started after its first force
  PerAtomRows::set_arrays(i);
  pending = 1;
}

int FixTDEMIntegrate::unpack_exchange(int nlocal, double *buf)
{
  if (buf[0] == 0.0) pending = 1;
  return PerAtomRows::unpack_exchange(nlocal, buf);
}

// per-atom restart record: [count incl. itself, code, started, history ...]
int FixTDEMIntegrate::pack_restart(int i, double *buf)
{
  const double head = code;
  const int n = pack_row(i, buf, &head);
  if (nlast && rows_[i][0] == 1.0) {  // written during a run: the force of this step is the last one
    buf[2] = 3.0;
    accelerations(i, buf + 2 + olast);
  }
  return n;
}

void FixTDEMIntegrate::unpack_restart(int nlocal, int nth)
{
  const double head = code;
  if (restart_mismatch) set_arrays(nlocal);
  else if (!unpack_row(nlocal, nth, &head)) pending = 1;
}

// global restart record: scheme/rotation code, time step of the histories, doubles per atom,
// the previous time step
void FixTDEMIntegrate::write_restart(FILE *fp)
{
  if (comm->me != 0) return;
  const double list[4] = {static_cast<double>(code), dt_hist, static_cast<double>(stride), dt_prev};
  const int size = sizeof(list);
  fwrite(&size, sizeof(int), 1, fp);
  fwrite(list, sizeof(double), 4, fp);
}

void FixTDEMIntegrate::restart(char *buf)
{
  const double *list = reinterpret_cast<const double *>(buf);
  const int stored_code = static_cast<int>(list[0]);
  if (stored_code != code || static_cast<int>(list[2]) != stride) {
    restart_mismatch = 1;
    pending = 1;
    if (comm->me == 0) {
      const int s = stored_code / 2;
      const std::string old = (s >= 0 && s < static_cast<int>(ti::Scheme::count))
                                  ? ti::info(static_cast<ti::Scheme>(s)).name
                                  : "?";
      error->warning(FLERR, fmt::format("fix {} tdem/integrate: the restart file holds the history of "
                                        "scheme {} (rotation {}), this fix uses scheme {} (rotation {}); "
                                        "every atom is started again",
                                        id, old, stored_code % 2 ? "yes" : "no",
                                        ti::info(scheme).name, rotation ? "yes" : "no"));
    }
    return;
  }
  dt_hist = list[1];
  dt_prev = list[3];
}

void *FixTDEMIntegrate::extract(const char *name, int &dim)
{
  dim = 0;
  if (std::strcmp(name, "tdem_energy_form") == 0) return energy_form_;
  return nullptr;
}
