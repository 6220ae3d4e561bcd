// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: fix tdem/wall/gran (see fix_tdem_wall_gran.h and docs/lammps/fix_tdem_wall_gran.md).

#include "fix_tdem_wall_gran.h"

#include "grid_host.h"

#include "contact/energy.h"

#include "atom.h"
#include "domain.h"
#include "error.h"
#include "memory.h"
#include "modify.h"
#include "neighbor.h"
#include "respa.h"
#include "update.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;
using tdem_lammps::LawCoeffs;

static constexpr double BIG = 1.0e20;

namespace {
double wall_number(LAMMPS *lmp, const std::string &where, const std::string &key, const char *s)
{
  char *end = nullptr;
  errno = 0;
  const double v = strtod(s, &end);
  if (end == s || *end != '\0' || errno == ERANGE || !std::isfinite(v))
    lmp->error->all(FLERR, where + ": " + key + " expects a finite number, got '" + s + "'");
  return v;
}
}  // namespace

/* ---------------------------------------------------------------------- */

FixTDEMWallGran::FixTDEMWallGran(LAMMPS *lmp, int narg, char **arg) :
    PerAtomRows(lmp, narg, arg)
{
  const std::string where = std::string("fix ") + id + " tdem/wall/gran";
  if (!atom->radius_flag || !atom->rmass_flag || !atom->omega_flag)
    error->all(FLERR, where + " requires atom_style sphere (per-atom radius, rmass, omega)");

  create_attribute = 1;
  restart_peratom = 1;
  nlevels_respa = 0;
  dt = update->dt;

  int iarg = tdem_lammps::parse_law(lmp, where, narg, arg, 3, true, law);
  energy_on = 0;

  // wall geometry
  if (iarg >= narg)
    error->all(FLERR, where + ": missing wall style; allowed: xplane lo hi, yplane lo hi, "
                              "zplane lo hi, zcylinder radius");
  const std::string ws = arg[iarg];
  cylradius = 0.0;
  lo = -BIG;
  hi = BIG;
  if (ws == "xplane" || ws == "yplane" || ws == "zplane") {
    wallstyle = (ws == "xplane") ? XPLANE : (ws == "yplane") ? YPLANE : ZPLANE;
    if (iarg + 3 > narg)
      error->all(FLERR, where + ": wall style " + ws + " needs 2 values (lo hi, NULL = no wall), got " +
                            std::to_string(narg - iarg - 1));
    if (strcmp(arg[iarg + 1], "NULL") != 0) lo = wall_number(lmp, where, ws + " lo", arg[iarg + 1]);
    if (strcmp(arg[iarg + 2], "NULL") != 0) hi = wall_number(lmp, where, ws + " hi", arg[iarg + 2]);
    if (lo == -BIG && hi == BIG)
      error->all(FLERR, where + ": wall style " + ws + " NULL NULL gives no wall; give lo, hi or both");
    if (!(lo < hi))
      error->all(FLERR, where + ": " + ws + " lo = " + arg[iarg + 1] + " must be below hi = " +
                            arg[iarg + 2]);
    iarg += 3;
  } else if (ws == "zcylinder") {
    wallstyle = ZCYLINDER;
    if (iarg + 2 > narg) error->all(FLERR, where + ": wall style zcylinder needs 1 value (radius), got 0");
    cylradius = wall_number(lmp, where, "zcylinder radius", arg[iarg + 1]);
    if (!(cylradius > 0.0))
      error->all(FLERR, where + ": zcylinder radius = " + arg[iarg + 1] + " must be > 0");
    lo = hi = 0.0;
    iarg += 2;
  } else {
    error->all(FLERR, where + ": wall style '" + ws +
                          "' is unknown; allowed: xplane, yplane, zplane, zcylinder");
  }

  // optional wall motion
  wiggle = wshear = 0;
  axis = 0;
  amplitude = period = omega = vshear = 0.0;
  while (iarg < narg) {
    const std::string key = arg[iarg];
    if (key == "wiggle" || key == "shear") {
      const int nval = (key == "wiggle") ? 3 : 2;
      if (iarg + nval + 1 > narg)
        error->all(FLERR, where + ": " + key + " needs " + std::to_string(nval) + " values (" +
                              (key == "wiggle" ? "dim amplitude period" : "dim velocity") +
                              "), got " + std::to_string(narg - iarg - 1));
      const std::string dim = arg[iarg + 1];
      if (dim == "x") axis = 0;
      else if (dim == "y") axis = 1;
      else if (dim == "z") axis = 2;
      else error->all(FLERR, where + ": " + key + " dimension '" + dim + "' is unknown; allowed: x, y, z");
      if (key == "wiggle") {
        amplitude = wall_number(lmp, where, "wiggle amplitude", arg[iarg + 2]);
        period = wall_number(lmp, where, "wiggle period", arg[iarg + 3]);
        if (!(period > 0.0))
          error->all(FLERR, where + ": wiggle period = " + arg[iarg + 3] + " must be > 0");
        wiggle = 1;
      } else {
        vshear = wall_number(lmp, where, "shear velocity", arg[iarg + 2]);
        wshear = 1;
      }
      iarg += nval + 1;
    } else if (key == "energy") {
      if (iarg + 1 >= narg) error->all(FLERR, where + ": energy needs a value, no or yes");
      const std::string val = arg[iarg + 1];
      if (val != "yes" && val != "no") error->all(FLERR, where + ": energy takes no or yes, got '" + val + "'");
      energy_on = val == "yes";
      iarg += 2;
    } else {
      error->all(FLERR, where + ": unexpected argument '" + key +
                            "'; allowed after the wall style: wiggle dim A T, shear dim V, energy no|yes");
    }
  }
  if (energy_on && law.gc)
    error->all(FLERR, where + ": energy yes with grid_correction on is not supported in LAMMPS yet; turn one off");
  // the tangential block + the normal law's slots (+ the rolling displacement); energy yes: the
  // current contact's slots, the ended contacts' energy per part and the wall's work
  law_width = tdem_lammps::law_history_size(law, law.tlaw);
  rows_init(law_width + (energy_on ? tdem::energy::kSlots + tdem::energy::kParts + 1 : 0), "tdem/wall/gran:history");

  if (wallstyle == XPLANE && domain->xperiodic)
    error->all(FLERR, where + ": xplane wall in a periodic dimension");
  if (wallstyle == YPLANE && domain->yperiodic)
    error->all(FLERR, where + ": yplane wall in a periodic dimension");
  if (wallstyle == ZPLANE && domain->zperiodic)
    error->all(FLERR, where + ": zplane wall in a periodic dimension");
  if (wallstyle == ZCYLINDER && (domain->xperiodic || domain->yperiodic))
    error->all(FLERR, where + ": zcylinder wall needs non-periodic x and y");
  if (wiggle && wshear) error->all(FLERR, where + ": cannot both wiggle and shear");
  if (wiggle && wallstyle == ZCYLINDER && axis != 2)
    error->all(FLERR, where + ": a zcylinder wall can wiggle along z only");
  if (wshear && wallstyle == axis)
    error->all(FLERR, where + ": a plane wall cannot shear along its own normal");

  if (wiggle) omega = 2.0 * M_PI / period;

  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);

  time_origin = update->ntimestep;
}

FixTDEMWallGran::~FixTDEMWallGran()
{
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
  rigid.destroy(memory);
}

int FixTDEMWallGran::setmask()
{
  int mask = 0;
  mask |= POST_FORCE;
  mask |= POST_FORCE_RESPA;
  return mask;
}

void FixTDEMWallGran::init()
{
  dt = update->dt;
  if (utils::strmatch(update->integrate_style, "^respa"))
    nlevels_respa = ((Respa *) update->integrate)->nlevels;
  rigid.find(modify);
  // fix tdem/clump with a multiple-contact correction: the corrected path
  // (the largest overlap is below the largest sphere diameter)
  double rmax = 0.0, all = 0.0;
  for (int i = 0; i < atom->nlocal; i++) rmax = MAX(rmax, atom->radius[i]);
  MPI_Allreduce(&rmax, &all, 1, MPI_DOUBLE, MPI_MAX, world);
  clump.find(lmp, std::string("fix ") + id + " tdem/wall/gran", 2.0 * all);
}

void FixTDEMWallGran::setup(int vflag)
{
  tdem_lammps::setup_post_force(this, update, vflag, nlevels_respa);
}

namespace {
struct WallRunner {
  FixTDEMWallGran *f;
  template <int M, int E, int S, int TL = 0> void run() { f->template eval<M, E, S, TL>(); }
};
// the corrected path: the law at run time, the tangential law at compile time
struct WallRunnerCorrected {
  FixTDEMWallGran *f;
  template <int M, int E, int S, int TL = 0> void run() { f->template eval<-1, -1, -1, TL, 1>(); }
};
// the energy accounting: the law at run time, the tangential law at compile time
struct WallRunnerEnergy {
  FixTDEMWallGran *f;
  template <int M, int E, int S, int TL = 0> void run() { f->template eval<-1, -1, -1, TL, 2>(); }
};
}  // namespace

void FixTDEMWallGran::post_force(int /*vflag*/)
{
  if (neighbor->ago == 0) rigid.refresh(atom, memory, "tdem/wall/gran:mass_rigid");
  if (clump.mode != 0) {
    if (energy_on)
      error->all(FLERR, std::string("fix ") + id + " tdem/wall/gran: energy yes with the multiple-contact "
                                                   "correction of fix tdem/clump is not supported yet");
    tdem_lammps::dispatch(false, law.mode, law.end, law.slip, law.tlaw, WallRunnerCorrected{this});
    return;
  }
  if (energy_on) {
    tdem_lammps::dispatch(false, law.mode, law.end, law.slip, law.tlaw, WallRunnerEnergy{this});
    return;
  }
  // rolling resistance and the time-grid correction run on the run-time path (the compile-time
  // ones have none, at no cost)
  tdem_lammps::dispatch(!law.roll && !law.gc, law.mode, law.end, law.slip, law.tlaw, WallRunner{this});
}

template <int M, int E, int S, int TL, int C> __attribute__((flatten, noinline)) void FixTDEMWallGran::eval()
{
  const bool history_update = !update->setupflag;

  // wall position and velocity
  double wlo = lo, whi = hi;
  double vwall0[3] = {0.0, 0.0, 0.0};
  if (wiggle) {
    const double arg = omega * (update->ntimestep - time_origin) * dt;
    if (wallstyle == axis) {
      wlo = lo + amplitude - amplitude * cos(arg);
      whi = hi + amplitude - amplitude * cos(arg);
    }
    vwall0[axis] = amplitude * omega * sin(arg);
  } else if (wshear)
    vwall0[axis] = vshear;

  const auto [x, v, f, omg, torque, radius, rmass, mask, nlocal] = tdem_lammps::sphere_arrays(atom);

  // C: the multiple-contact correction; count / overlap tally the body-wall contacts first (in
  // the order of the force pass below)
  [[maybe_unused]] tdem_lammps::ClumpView cv;
  [[maybe_unused]] std::size_t kcorr = 0;
  [[maybe_unused]] const tdem::clumps::Correction cmode = clump.correction();
  [[maybe_unused]] const bool share = clump.shares();
  if constexpr (C == 1) {
    cv.fetch(clump.fix, cmode == tdem::clumps::Correction::local_mass);
    if (share) {
      clump.tally.clear();
      for (int i = 0; i < nlocal; i++) {
        if (!(mask[i] & groupbit) || cv.body[i] < 0) continue;
        double d[3] = {0.0, 0.0, 0.0};
        std::int64_t side = -1;
        if (wallstyle == ZCYLINDER) {
          const double delxy = sqrt(x[i][0] * x[i][0] + x[i][1] * x[i][1]);
          const double delr = cylradius - delxy;
          if (delr > radius[i]) continue;
          d[0] = -delr / delxy * x[i][0];
          d[1] = -delr / delxy * x[i][1];
          side = -3;
        } else {
          const double del1 = x[i][wallstyle] - wlo, del2 = whi - x[i][wallstyle];
          d[wallstyle] = (del1 < del2) ? del1 : -del2;
          side = (del1 < del2) ? -1 : -2;
        }
        const double rsq = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
        if (rsq > radius[i] * radius[i]) continue;
        clump.tally.add(cv.key[i], side, radius[i] - sqrt(rsq));
      }
      clump.merge(lmp);
    }
  }

  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    double dx = 0.0, dy = 0.0, dz = 0.0;
    double vwall[3] = {vwall0[0], vwall0[1], vwall0[2]};

    if (wallstyle == XPLANE) {
      const double del1 = x[i][0] - wlo, del2 = whi - x[i][0];
      dx = (del1 < del2) ? del1 : -del2;
    } else if (wallstyle == YPLANE) {
      const double del1 = x[i][1] - wlo, del2 = whi - x[i][1];
      dy = (del1 < del2) ? del1 : -del2;
    } else if (wallstyle == ZPLANE) {
      const double del1 = x[i][2] - wlo, del2 = whi - x[i][2];
      dz = (del1 < del2) ? del1 : -del2;
    } else {
      const double delxy = sqrt(x[i][0] * x[i][0] + x[i][1] * x[i][1]);
      const double delr = cylradius - delxy;
      if (delr > radius[i]) {
        dz = cylradius;
      } else {
        dx = -delr / delxy * x[i][0];
        dy = -delr / delxy * x[i][1];
        if (wshear && axis != 2) {  // rotating cylinder: tangential wall velocity
          vwall[0] = vshear * x[i][1] / delxy;
          vwall[1] = -vshear * x[i][0] / delxy;
          vwall[2] = 0.0;
        }
      }
    }

    const double rsq = dx * dx + dy * dy + dz * dz;
    const double rad = radius[i];
    double *shear = rows_[i];
    [[maybe_unused]] double *es = shear + law_width;  // energy yes: the contact's slots
    if constexpr (M < 0) {
      // grid_correction: the first step after a corrected contact gets the end's impulse; the
      // whole row (with the correction's values) is forgotten
      if (law.gc && rsq > rad * rad) {
        if (history_update) gc_separation_wall(i, shear, vwall);
        for (int m = 0; m < width_; m++) shear[m] = 0.0;
        continue;
      }
    }
    if (rsq > rad * rad) {
      if constexpr (C == 2) {  // energy: a contact at the last step (a unit normal saved) has ended
        if (es[0] != 0.0 || es[1] != 0.0 || es[2] != 0.0) energy_end(i, es, vwall, history_update);
      }
      if (TL != tdem_lammps::TLAW_CUNDALL_STRACK) {
        tdem_lammps::clear_history<(TL > 0 ? TL : 0)>(shear, law_width);
        continue;
      }
      shear[0] = shear[1] = shear[2] = 0.0;
      tdem_lammps::clear_law_history(shear, law_width);
      continue;
    }
    // a centre on the wall surface has no normal: stop with the atom ID instead of NaN forces
    if (__builtin_expect(!(rsq > 0.0), 0)) centre_on_wall(i);

    double meff = rigid.of(i, rmass[i]);

    const double r = sqrt(rsq);
    if constexpr (C == 1) {
      if (cv.body[i] >= 0 && cmode == tdem::clumps::Correction::local_mass) {
        // locally reduced mass at the contact point (middle of the overlap); the wall adds 0
        const double n[3] = {dx / r, dy / r, dz / r};
        const double h = rad - 0.5 * (rad - r);
        const double xc[3] = {x[i][0] - n[0] * h, x[i][1] - n[1] * h, x[i][2] - n[2] * h};
        meff = 1.0 / cv.inverse_local_mass(domain, cv.body[i], xc, n);
      }
    }
    const double rinv = 1.0 / r;
    const double rsqinv = 1.0 / rsq;
    const double vr1 = v[i][0] - vwall[0];
    const double vr2 = v[i][1] - vwall[1];
    const double vr3 = v[i][2] - vwall[2];
    const double wr1 = rad * omg[i][0] * rinv;
    const double wr2 = rad * omg[i][1] * rinv;
    const double wr3 = rad * omg[i][2] * rinv;

    double ccel, fs[3], troll[3] = {0.0, 0.0, 0.0};
    [[maybe_unused]] tdem::NormalResult<double> nres{};
    bool corrected = false;
    if constexpr (M < 0) {
      if (law.gc && history_update && tdem_lammps::gc_needs(law, E, shear[width_ - 1] == 0.0, shear, width_)) {
        const tdem_lammps::GcContact k{&law, meff, dx, dy, dz, r, rinv, rsqinv, rad - r, {vr1, vr2, vr3},
                                       {wr1, wr2, wr3}, dt, rad, 0.0, omg[i], nullptr};
        tdem_lammps::gc_contact(k, shear, width_, ccel, fs, troll);
        corrected = true;
      }
    }
    if (!corrected)
      tdem_lammps::evaluate_contact<M, E, S, TL>(law, meff, dx, dy, dz, r, rinv, rsqinv, rad - r, vr1,
                                                 vr2, vr3, wr1, wr2, wr3, dt, history_update, shear,
                                                 ccel, fs, rad, 0.0, omg[i], nullptr, troll,
                                                 C == 2 ? &nres : nullptr);
    if constexpr (C == 1) {
      // count / overlap: the whole contact force times s (the history stays the law's own)
      if (cv.body[i] >= 0 && share) {
        const double sc = clump.tally.factor(cmode, kcorr++, rad - r);
        ccel *= sc;
        fs[0] *= sc;
        fs[1] *= sc;
        fs[2] *= sc;
      }
    }

    if constexpr (C == 2) {
      // energy: the step's work of the parts over the motion relative to the wall, and the wall's
      // work on the sphere over the wall's own motion (trapezoid of the force on the sphere); at
      // set-up the loads only
      namespace en = tdem::energy;
      const en::Compact<double> now =
          tdem_lammps::contact_loads(dx, dy, dz, rinv, ccel * r, nres.elastic, fs, rad, 0.0, law.roll ? troll : nullptr);
      static const double rest[3] = {0.0, 0.0, 0.0};
      if (history_update)
        en::wall_step(es, now, en::pair_motion(v[i], vwall, omg[i], rest, dt), vwall, dt, es[en::kSlots + en::kParts]);
      else
        en::save(now, es);
    }

    double fw[3];
    tdem_lammps::add_wall_force(f[i], torque[i], dx, dy, dz, ccel, fs, rinv, rad, fw);
    if constexpr (M < 0) {  // rolling resistance against the wall (at rest)
      if (law.roll) {
        torque[i][0] += troll[0];
        torque[i][1] += troll[1];
        torque[i][2] += troll[2];
      }
    }
  }
}

// The first step without contact of atom i with the wall, grid_correction on: the end's extra
// impulse (grid_host.h). The wall geometry again, with the true normal also for a cylinder (the
// contact loop puts an atom far from it off along z). Cold: once per contact.
void FixTDEMWallGran::gc_separation_wall(int i, const double *shear, const double *vwall0)
{
  double **x = atom->x, **v = atom->v, **omg = atom->omega;
  const double rad = atom->radius[i];
  double d[3] = {0.0, 0.0, 0.0}, vwall[3] = {vwall0[0], vwall0[1], vwall0[2]};
  if (wallstyle == ZCYLINDER) {
    const double delxy = sqrt(x[i][0] * x[i][0] + x[i][1] * x[i][1]);
    if (!(delxy > 0.0)) return;
    const double delr = cylradius - delxy;
    d[0] = -delr / delxy * x[i][0];
    d[1] = -delr / delxy * x[i][1];
    if (wshear && axis != 2) {
      vwall[0] = vshear * x[i][1] / delxy;
      vwall[1] = -vshear * x[i][0] / delxy;
      vwall[2] = 0.0;
    }
  } else {
    double wlo = lo, whi = hi;
    if (wiggle && wallstyle == axis) {
      const double arg = omega * (update->ntimestep - time_origin) * dt;
      wlo = lo + amplitude - amplitude * cos(arg);
      whi = hi + amplitude - amplitude * cos(arg);
    }
    const double del1 = x[i][wallstyle] - wlo, del2 = whi - x[i][wallstyle];
    d[wallstyle] = (del1 < del2) ? del1 : -del2;
  }
  const double rsq = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  if (!(rsq > 0.0)) return;
  const double r = sqrt(rsq), rinv = 1.0 / r;
  const tdem_lammps::GcContact k{&law, rigid.of(i, atom->rmass[i]), d[0], d[1], d[2], r, rinv, 1.0 / rsq, rad - r,
                                 {v[i][0] - vwall[0], v[i][1] - vwall[1], v[i][2] - vwall[2]},
                                 {rad * omg[i][0] * rinv, rad * omg[i][1] * rinv, rad * omg[i][2] * rinv},
                                 dt, rad, 0.0, omg[i], nullptr};
  double ccel, fs[3], fw[3];
  if (tdem_lammps::gc_separation(k, shear, width_, ccel, fs))
    tdem_lammps::add_wall_force(atom->f[i], atom->torque[i], d[0], d[1], d[2], ccel, fs, rinv, rad, fw);
}

// energy yes: the first step without contact of atom i with the wall: the last half step of its
// loads (over the motion relative to the wall; the wall's work over its own), then the contact's
// energy to the atom's ended sums and its slots zeroed
void FixTDEMWallGran::energy_end(int i, double *slots, const double *vwall, bool update)
{
  namespace en = tdem::energy;
  static const double rest[3] = {0.0, 0.0, 0.0};
  if (update)
    en::wall_step(slots, en::Compact<double>{}, en::pair_motion(atom->v[i], vwall, atom->omega[i], rest, dt), vwall,
                  dt, slots[en::kSlots + en::kParts]);
  en::close(slots, slots + en::kSlots);
}

void FixTDEMWallGran::energy_sums(double *parts, double *work, double **peratom, int wall_column) const
{
  namespace en = tdem::energy;
  if (!energy_on) return;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    const double *es = rows_[i] + law_width;
    for (int p = 0; p < en::kParts; p++) {
      const double taken = es[en::kSlots + p] - es[en::kCompactSize + p];
      parts[p] += taken;
      if (peratom) peratom[i][p] += taken;
    }
    *work += es[en::kSlots + en::kParts];
    if (peratom) peratom[i][wall_column] += es[en::kSlots + en::kParts];
  }
}

void FixTDEMWallGran::centre_on_wall(int i) {
  static const char *const names[] = {"xplane", "yplane", "zplane", "zcylinder"};
  error->one(FLERR, std::string("fix ") + id + " tdem/wall/gran: atom " +
                        std::to_string(static_cast<long long>(atom->tag[i])) + " has its centre on the " +
                        names[wallstyle] + " wall (distance 0) at step " +
                        std::to_string(static_cast<long long>(update->ntimestep)) +
                        ": the contact normal is undefined; place the particle off the wall");
}

void FixTDEMWallGran::post_force_respa(int vflag, int ilevel, int /*iloop*/)
{
  if (ilevel == nlevels_respa - 1) post_force(vflag);
}

double FixTDEMWallGran::memory_usage()
{
  return rows_memory() + rigid.memory_usage();
}

void FixTDEMWallGran::reset_dt()
{
  dt = update->dt;
}
