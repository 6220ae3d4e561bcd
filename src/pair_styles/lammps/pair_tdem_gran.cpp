// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: pair style tdem/gran (see pair_tdem_gran.h and docs/lammps/pair_tdem_gran.md).
//
// Bookkeeping follows the LAMMPS conventions for granular pair styles with history: a
// FixNeighHistory stores the tangential block (3 values: the spring elongation of
// cundall_strack, linear_spring, mindlin_no_slip, di_renzo, unused for haff_werner; 8 for
// walton_braun, 13 for mindlin_deresiewicz) per neighbour with a touch flag, then the normal
// law's slots (+1 with walton_braun: xi_max; +2 with thornton: xi_max, f_max; power_law: the
// slots of tdem::power_law;
// +3 with extended_linear: v0, k, gamma; +2 with extended_hertz: v0, alpha), the
// pair asks for a size neighbour list with history, meff uses fix freeze and
// fix rigid body masses, and the cutoff is the sum of the largest radii (including particles
// a fix pour / fix deposit will insert). The set-up (arguments, coefficients, cutoffs, restart)
// is in pair_tdem_gran_setup.cpp.

#include "pair_tdem_gran.h"

#include "grid_host.h"
#include "fix_tdem_energy_store.h"

#include "contact/energy.h"
#include "tdem_lammps_energy.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix.h"
#include "fix_neigh_history.h"
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "neigh_request.h"
#include "neighbor.h"
#include "update.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using tdem_lammps::LawCoeffs;

/* ---------------------------------------------------------------------- */

PairTDEMGran::PairTDEMGran(LAMMPS *lmp) : Pair(lmp)
{
  single_enable = 1;
  single_extra = 10;  // fs_x fs_y fs_z |fs| vn_x vn_y vn_z vt_x vt_y vt_z (as gran/hooke/history)
  svector = new double[single_extra];
  neighprev = 0;
  no_virial_fdotr_compute = 1;
  centroidstressflag = CENTROID_NOTAVAIL;
  finitecutflag = 1;
  restartinfo = 1;
  size_history = tdem::cundall_strack::history_size;
  comm_forward = 1;               // rigid body masses
  nondefault_history_transfer = 0;  // history[j][i] = -history[i][j] (shear flips sign);
                                    // 1 with walton_braun/thornton (init_style)

  onerad_dynamic = onerad_frozen = maxrad_dynamic = maxrad_frozen = nullptr;
  uniform = true;
  umode = uend = uslip = 0;
  utlaw = 0;
  one_law = false;
  gc_any = false;
  energy_on = 0;
  estore = nullptr;
  atom_ntypes = 0;
  dt = 0.0;
  freeze_group_bit = 0;
  restart_history_tags = -2;
  restart_history_size = 0;

  // placeholder for the FixNeighHistory, so it keeps the input-script position in the fix list
  fix_history = nullptr;
  id_dummy = "NEIGH_HISTORY_TDEM_DUMMY" + std::to_string(instance_me);
  id_history = "NEIGH_HISTORY_TDEM" + std::to_string(instance_me);
  id_estore = "TDEM_ENERGY_STORE" + std::to_string(instance_me);
  modify->add_fix(id_dummy + " all DUMMY");
}

/* ---------------------------------------------------------------------- */

PairTDEMGran::~PairTDEMGran()
{
  if (copymode) return;
  delete[] svector;
  if (!fix_history)
    modify->delete_fix(id_dummy);
  else
    modify->delete_fix(id_history);
  if (estore) modify->delete_fix(id_estore);

  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(cutsq);
    delete[] onerad_dynamic;
    delete[] onerad_frozen;
    delete[] maxrad_dynamic;
    delete[] maxrad_frozen;
  }
  rigid.destroy(memory);
}

/* ---------------------------------------------------------------------- */

namespace {
struct PairRunner {
  PairTDEMGran *p;
  int eflag, vflag;
  bool one;               // every type pair has the same coefficients ...
  const LawCoeffs *law1;  // ... these
  template <int M, int E, int S, int TL = 0> void run() {
    // the single-coefficient paths (ONE = 1; ONE = 2 with grid_correction on) for the
    // compile-time laws of cundall_strack
    if constexpr (M >= 0 && TL == 0) {
      if (one) {
        if (law1->gc) return one_law<M, E, S, TL, 2>();
        return one_law<M, E, S, TL, 1>();
      }
    }
    p->template eval<M, E, S, TL>(eflag, vflag);
  }
  template <int M, int E, int S, int TL, int ONE> void one_law() {
    // normal hertz: end, slip and the damping member fixed at compile time too
    if constexpr (M == tdem_lammps::MODE_HERTZ) {
      using namespace tdem_lammps;
#define TDEM_LMP_HCASE(e, s, d)                                            \
  if (law1->end == e && law1->slip == s && law1->hdamp == d)               \
    return p->template eval<M, e, s, TL, ONE, d>(eflag, vflag);
#define TDEM_LMP_HCASES(d) \
  TDEM_LMP_HCASE(0, 0, d) TDEM_LMP_HCASE(0, 1, d) TDEM_LMP_HCASE(1, 0, d) TDEM_LMP_HCASE(1, 1, d)
      TDEM_LMP_HCASES(HDAMP_LINEAR) TDEM_LMP_HCASES(HDAMP_KK)
      TDEM_LMP_HCASES(HDAMP_TSUJI) TDEM_LMP_HCASES(HDAMP_GENERAL)
#undef TDEM_LMP_HCASES
#undef TDEM_LMP_HCASE
    }
    p->template eval<M, E, S, TL, ONE>(eflag, vflag);
  }
};
// the corrected path (fix tdem/clump correction count|overlap|local_mass): the law at run time,
// the tangential law at compile time
struct PairRunnerCorrected {
  PairTDEMGran *p;
  int eflag, vflag;
  template <int M, int E, int S, int TL = 0> void run() { p->template eval<-1, -1, -1, TL, 0, -1, 1>(eflag, vflag); }
};
// the energy accounting (energy yes): the law at run time, the tangential law at compile time
struct PairRunnerEnergy {
  PairTDEMGran *p;
  int eflag, vflag;
  template <int M, int E, int S, int TL = 0> void run() { p->template eval<-1, -1, -1, TL, 0, -1, 2>(eflag, vflag); }
};
}  // namespace

void PairTDEMGran::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);

  // rigid body masses of owned and ghost atoms (as the LAMMPS granular styles)
  if (rigid.fix && neighbor->ago == 0) {
    rigid.refresh(atom, memory, "pair:mass_rigid");
    tdem_lammps::compat::forward_comm(comm, this);
  }

  // the energy accounting: a separate instantiation; the ended contacts' halves of ghost atoms go
  // to their owners after the loop
  if (energy_on) {
    estore->clear_ghosts();
    tdem_lammps::dispatch(false, umode, uend, uslip, utlaw, PairRunnerEnergy{this, eflag, vflag});
    estore->fold();
    if (vflag_fdotr) virial_fdotr_compute();
    return;
  }

  // the multiple-contact correction of fix tdem/clump: a separate instantiation
  if (clump.mode != 0) {
    tdem_lammps::dispatch(false, umode, uend, uslip, utlaw, PairRunnerCorrected{this, eflag, vflag});
    if (vflag_fdotr) virial_fdotr_compute();
    return;
  }

  // compile-time paths when every type pair has the same law (and so the history size of
  // that law); with grid_correction on only when every type pair has the same coefficients
  // (ONE = 2), else the run-time path
  const int law_hsize = tdem_lammps::history_size(umode, utlaw);
  const bool compile_time =
      uniform && (gc_any ? one_law && coeffs(1, 1).gc && size_history == law_hsize + tdem::grid::history_size
                         : size_history == law_hsize);
  tdem_lammps::dispatch(compile_time, umode, uend, uslip, utlaw, PairRunner{this, eflag, vflag, one_law, &coeffs(1, 1)});

  if (vflag_fdotr) virial_fdotr_compute();
}

// flatten: inline the kernels into each instantiation (the inliner's size limits would keep
// cundall_strack::force out of line, which costs ~10 % of the pair time); noinline keeps the
// instantiations out of the dispatcher.
// Instructions of the pair compute on the chute / the settled bed (callgrind,
// bench/lammps/callgrind_pair.sh), each step against the one before: ONE (no per-type lookups)
// -3.6 % / +1.0 %; __builtin_expect on the non-touching branch (the register allocator then
// keeps the pointers of that short, frequent path in registers) -1.6 % / -0.2 %; ONE's law as
// a local copy (its members become loop invariants: the force and touch stores cannot alias
// them) -1.3 % / -1.1 %; hertz end, slip and damping at compile time 0 / -5.3 %.
template <int M, int E, int S, int TL, int ONE, int D, int C>
__attribute__((flatten, noinline)) void PairTDEMGran::eval(int /*eflag*/, int /*vflag*/)
{
  const bool shearupdate = !update->setupflag;

  double **x = atom->x;
  double **v = atom->v;
  double **f = atom->f;
  double **omega = atom->omega;
  double **torque = atom->torque;
  double *radius = atom->radius;
  double *rmass = atom->rmass;
  int *mask = atom->mask;
  int *type = atom->type;
  const int nlocal = atom->nlocal;
  const int newton_pair = force->newton_pair;
  const int ntp1 = atom_ntypes + 1;
  const LawCoeffs *lawtab = law.data();
  // ONE: every type pair has the law of type pair 1 1; a local copy, so that its members are
  // loop invariants (the force and touch stores cannot alias them)
  const LawCoeffs law1 = lawtab[ntp1 + 1];
  // history values per neighbour: fixed on the compile-time paths, else size_history
  // (a constant expression on those paths, so that the unused stores of clear_*_history vanish);
  // G: grid_correction on (ONE = 2), its flags slot last
  constexpr bool G = ONE == 2;
  constexpr int hsize_m = M >= 0 ? tdem_lammps::history_size(M, TL > 0 ? TL : 0) + (G ? tdem::grid::history_size : 0) : 0;
  const int hsize = M >= 0 ? hsize_m : size_history;

  const int inum = list->inum;
  int *ilist = list->ilist;
  int *numneigh = list->numneigh;
  int **firstneigh = list->firstneigh;
  int **firsttouch = fix_history->firstflag;
  double **firstshear = fix_history->firstvalue;

  // C = 1: the multiple-contact correction. Sides of a contact: the body index of a clump sphere,
  // -(tag + 1) of a free sphere. count / overlap: every touching contact with a clump on at least
  // one side is tallied first (same loop order as the force pass below, k-th contact = k-th add)
  [[maybe_unused]] tdem_lammps::ClumpView cv;
  [[maybe_unused]] std::size_t kcorr = 0;
  [[maybe_unused]] const tdem::clumps::Correction cmode = clump.correction();
  [[maybe_unused]] const bool share = clump.shares();
  [[maybe_unused]] tagint *tag = atom->tag;
  if constexpr (C == 1) {
    cv.fetch(clump.fix, cmode == tdem::clumps::Correction::local_mass);
    if (share) {
      clump.tally.clear();
      for (int ii = 0; ii < inum; ii++) {
        const int i = ilist[ii];
        const int *jl = firstneigh[i];
        for (int jj = 0; jj < numneigh[i]; jj++) {
          const int j = jl[jj] & NEIGHMASK;
          if (cv.body[i] < 0 && cv.body[j] < 0) continue;
          const double dx = x[i][0] - x[j][0], dy = x[i][1] - x[j][1], dz = x[i][2] - x[j][2];
          const double rsq = dx * dx + dy * dy + dz * dz;
          const double rs = radius[i] + radius[j];
          if (rsq >= rs * rs) continue;
          const double xi = rs - sqrt(rsq);
          // sides: the body key (molecule ID, the same on every rank), a free sphere -(tag + 1)
          const std::int64_t a = cv.body[i] >= 0 ? cv.key[i] : -(std::int64_t) tag[i] - 1;
          const std::int64_t b = cv.body[j] >= 0 ? cv.key[j] : -(std::int64_t) tag[j] - 1;
          // newton off: a pair with a ghost j is also in the list of the rank (or image) owning
          // j; it is counted where tag[i] <= tag[j] (equal: two images of one sphere, two contacts)
          clump.tally.add(a, b, xi, newton_pair || j < nlocal || tag[i] <= tag[j]);
        }
      }
      clump.merge(lmp);
    }
  }

  // grid_correction: the contacts whose step needs it (start, end, watched clip) are deferred to
  // after the loop as (i, jj), a separation as (~i, jj): a call in the loop would keep the loop's
  // doubles in memory (SSE registers are caller-saved), 6 % of the loop on the chute
  [[maybe_unused]] int *defer = nullptr;
  [[maybe_unused]] int ndefer = 0;
  if constexpr ((M < 0 || G) && C == 0) {
    if (G || gc_any) {
      if (neighbor->ago == 0 || gc_defer.empty()) {  // sized by the list (at most every neighbour once)
        std::size_t nn = 0;
        for (int ii = 0; ii < inum; ii++) nn += numneigh[ilist[ii]];
        if (gc_defer.size() < 2 * nn + 2) gc_defer.resize(2 * nn + 2);
      }
      defer = gc_defer.data();
    }
  }

  for (int ii = 0; ii < inum; ii++) {
    const int i = ilist[ii];
    const double xtmp = x[i][0];
    const double ytmp = x[i][1];
    const double ztmp = x[i][2];
    const double radi = radius[i];
    const LawCoeffs *lawrow = ONE != 0 ? nullptr : lawtab + type[i] * ntp1;
    int *touch = firsttouch[i];
    double *allshear = firstshear[i];
    int *jlist = firstneigh[i];
    const int jnum = numneigh[i];

    for (int jj = 0; jj < jnum; jj++) {
      int j = jlist[jj];
      j &= NEIGHMASK;

      const double delx = xtmp - x[j][0];
      const double dely = ytmp - x[j][1];
      const double delz = ztmp - x[j][2];
      const double rsq = delx * delx + dely * dely + delz * delz;
      const double radj = radius[j];
      const double radsum = radi + radj;
      double *shear = &allshear[hsize * jj];

      // most neighbours do not touch (the list holds the skin too): tell the register allocator
      if (__builtin_expect(rsq >= radsum * radsum, 1)) {
        if constexpr (C == 2) {  // energy: the contact's last half step, its work to its atoms
          if (touch[jj]) energy_end(i, j, shear + hsize - tdem::energy::kSlots, shearupdate);
        }
        if constexpr (M < 0 || G) {
          // grid_correction: the first step after a corrected contact gets the end's impulse;
          // the whole block (with the correction's values) is forgotten
          // (a neighbour that did not touch at the last step has a cleared block already)
          if (G || gc_any) {
            if (touch[jj]) {
              touch[jj] = 0;
              const LawCoeffs &lw = ONE != 0 ? law1 : lawrow[type[j]];
              if (lw.gc && shearupdate && tdem_lammps::gc_flags(shear, hsize) == tdem::grid::kFlagOn) {
                if constexpr (C == 0) {  // after the loop (no call in it: see gc_defer)
                  defer[ndefer++] = ~i;
                  defer[ndefer++] = jj;
                  continue;
                } else {
                  const tdem_lammps::GcContact k = gc_pair_contact(i, j, lw);
                  double cx, fsx[3];
                  static const double none[3] = {0.0, 0.0, 0.0};
                  if (tdem_lammps::gc_separation<M, E, S, TL, D>(k, shear, hsize, cx, fsx))
                    gc_add_force(i, j, k, cx, fsx, none);
                }
              }
              for (int m = 0; m < hsize; m++) shear[m] = 0.0;
            }
            continue;
          }
        }
        // not touching: forget the history (energy: its slots are zero already, energy_end
        // cleared them at the contact's end)
        touch[jj] = 0;
        const int hclear = C == 2 ? hsize - tdem::energy::kSlots : hsize;
        if (TL != tdem_lammps::TLAW_CUNDALL_STRACK) {
          tdem_lammps::clear_history<(TL > 0 ? TL : 0)>(shear, hclear);
          continue;
        }
        shear[0] = 0.0;
        shear[1] = 0.0;
        shear[2] = 0.0;
        tdem_lammps::clear_law_history(shear, hclear);
        continue;
      }
      // coincident centres have no normal: stop with the two atom IDs instead of NaN forces
      if (__builtin_expect(!(rsq > 0.0), 0)) coincident_centres(i, j);

      const double r = sqrt(rsq);
      const double rinv = 1.0 / r;
      const double rsqinv = 1.0 / rsq;

      // relative translational and rotational velocity
      const double vr1 = v[i][0] - v[j][0];
      const double vr2 = v[i][1] - v[j][1];
      const double vr3 = v[i][2] - v[j][2];
      const double wr1 = (radi * omega[i][0] + radj * omega[j][0]) * rinv;
      const double wr2 = (radi * omega[i][1] + radj * omega[j][1]) * rinv;
      const double wr3 = (radi * omega[i][2] + radj * omega[j][2]) * rinv;

      // effective mass: rigid body masses; a frozen partner has infinite mass
      const double mi = rigid.of(i, rmass[i]);
      const double mj = rigid.of(j, rmass[j]);
      double meff = mi * mj / (mi + mj);
      if (mask[i] & freeze_group_bit) meff = mj;
      if (mask[j] & freeze_group_bit) meff = mi;
      [[maybe_unused]] const bool clump_contact = C == 1 && (cv.body[i] >= 0 || cv.body[j] >= 0);
      if constexpr (C == 1) {
        if (clump_contact && cmode == tdem::clumps::Correction::local_mass) {
          // locally reduced mass: inverse masses of the two sides at the contact point (middle
          // of the overlap on the line of centres); a free sphere 1/m, a frozen one 0
          const double n[3] = {delx * rinv, dely * rinv, delz * rinv};
          const double hi = radi - 0.5 * (radsum - r), hj = radj - 0.5 * (radsum - r);
          double inv = 0.0;
          if (!(mask[i] & freeze_group_bit)) {
            if (cv.body[i] >= 0) {
              const double xc[3] = {xtmp - n[0] * hi, ytmp - n[1] * hi, ztmp - n[2] * hi};
              inv += cv.inverse_local_mass(domain, cv.body[i], xc, n);
            } else
              inv += 1.0 / rmass[i];
          }
          if (!(mask[j] & freeze_group_bit)) {
            if (cv.body[j] >= 0) {
              const double xc[3] = {x[j][0] + n[0] * hj, x[j][1] + n[1] * hj, x[j][2] + n[2] * hj};
              inv += cv.inverse_local_mass(domain, cv.body[j], xc, n);
            } else
              inv += 1.0 / rmass[j];
          }
          meff = 1.0 / inv;
        }
      }

      [[maybe_unused]] const int was_touching = (M < 0 || G) ? touch[jj] : 1;
      touch[jj] = 1;
      const LawCoeffs &lawij = ONE != 0 ? law1 : lawrow[type[j]];
      double ccel, fs[3], troll[3] = {0.0, 0.0, 0.0};
      [[maybe_unused]] tdem::NormalResult<double> nres{};
      bool corrected = false;
      if constexpr (M < 0 || G) {
        // the time-grid correction (grid_host.h): a contact's first step and the watched clip of
        // a zero-force law; its other steps are the plain law below
        if ((G || lawij.gc) && shearupdate &&
            __builtin_expect(tdem_lammps::gc_needs(lawij, E, !was_touching, shear, hsize), 0)) {
          if constexpr (C == 0) {  // after the loop (no call in it: see gc_defer)
            defer[ndefer++] = i;
            defer[ndefer++] = jj;
            continue;
          } else {
            const tdem_lammps::GcContact k{&lawij, meff, delx, dely, delz, r, rinv, rsqinv, radsum - r,
                                           {vr1, vr2, vr3}, {wr1, wr2, wr3}, dt, radi, radj, omega[i], omega[j]};
            tdem_lammps::gc_contact<M, E, S, TL, D>(k, shear, hsize, ccel, fs, troll);
            corrected = true;
          }
        }
      }
      if (!corrected)
        tdem_lammps::evaluate_contact<M, E, S, TL, D>(lawij, meff, delx, dely,
                                                      delz, r, rinv, rsqinv, radsum - r, vr1, vr2,
                                                      vr3, wr1, wr2, wr3, dt, shearupdate, shear,
                                                      ccel, fs, radi, radj, omega[i], omega[j], troll,
                                                      C == 2 ? &nres : nullptr);
      if constexpr (C == 1) {
        // count / overlap: the whole contact force (normal and tangential) times s; the stored
        // tangential history is the law's own
        if (clump_contact && share) {
          const double sc = clump.tally.factor(cmode, kcorr++, radsum - r);
          ccel *= sc;
          fs[0] *= sc;
          fs[1] *= sc;
          fs[2] *= sc;
        }
      }

      if constexpr (C == 2) {
        // energy: the loads of this step in their parts; the step's work from the last step's
        // loads over the pair's motion (the half-step velocities of the drift); at set-up the
        // loads only (the integrator's first kick uses them)
        const tdem::energy::Compact<double> now = tdem_lammps::contact_loads(
            delx, dely, delz, rinv, ccel * r, nres.elastic, fs, radi, radj, lawij.roll ? troll : nullptr);
        double *es = shear + hsize - tdem::energy::kSlots;
        if (shearupdate)
          tdem::energy::step(es, now, tdem::energy::pair_motion(v[i], v[j], omega[i], omega[j], dt));
        else
          tdem::energy::save(now, es);
      }

      // forces and torques
      const double fx = delx * ccel + fs[0];
      const double fy = dely * ccel + fs[1];
      const double fz = delz * ccel + fs[2];
      f[i][0] += fx;
      f[i][1] += fy;
      f[i][2] += fz;

      const double tor1 = rinv * (dely * fs[2] - delz * fs[1]);
      const double tor2 = rinv * (delz * fs[0] - delx * fs[2]);
      const double tor3 = rinv * (delx * fs[1] - dely * fs[0]);
      torque[i][0] -= radi * tor1;
      torque[i][1] -= radi * tor2;
      torque[i][2] -= radi * tor3;

      if (newton_pair || j < nlocal) {
        f[j][0] -= fx;
        f[j][1] -= fy;
        f[j][2] -= fz;
        torque[j][0] -= radj * tor1;
        torque[j][1] -= radj * tor2;
        torque[j][2] -= radj * tor3;
      }
      if constexpr (M < 0) {  // rolling resistance (run-time path only): -troll on j
        if (lawij.roll) {
          torque[i][0] += troll[0];
          torque[i][1] += troll[1];
          torque[i][2] += troll[2];
          if (newton_pair || j < nlocal) {
            torque[j][0] -= troll[0];
            torque[j][1] -= troll[1];
            torque[j][2] -= troll[2];
          }
        }
      }

      if (evflag) ev_tally_xyz(i, j, nlocal, newton_pair, 0.0, 0.0, fx, fy, fz, delx, dely, delz);
    }
  }
  if constexpr ((M < 0 || G) && C == 0) {
    if (ndefer) gc_deferred<M, E, S, TL, D>(defer, ndefer, ONE != 0 ? &law1 : nullptr);
  }
}

// The contacts eval deferred (grid_correction, grid_host.h): their steps and forces as in eval.
template <int M, int E, int S, int TL, int D>
__attribute__((noinline)) void PairTDEMGran::gc_deferred(const int *defer, int n, const LawCoeffs *one)
{
  const int ntp1 = atom_ntypes + 1, hsize = size_history;
  for (int k = 0; k < n; k += 2) {
    const bool ends = defer[k] < 0;
    const int i = ends ? ~defer[k] : defer[k], jj = defer[k + 1];
    const int j = list->firstneigh[i][jj] & NEIGHMASK;
    double *shear = &fix_history->firstvalue[i][hsize * jj];
    const LawCoeffs &lw = one ? *one : law[atom->type[i] * ntp1 + atom->type[j]];
    const tdem_lammps::GcContact c = gc_pair_contact(i, j, lw);
    double ccel, fs[3], troll[3] = {0.0, 0.0, 0.0};
    if (ends) {
      // the first step without contact: the end's extra impulse, then the history is forgotten
      if (tdem_lammps::gc_separation<M, E, S, TL, D>(c, shear, hsize, ccel, fs)) gc_add_force(i, j, c, ccel, fs, troll);
      for (int m = 0; m < hsize; m++) shear[m] = 0.0;
      continue;
    }
    tdem_lammps::gc_contact<M, E, S, TL, D>(c, shear, hsize, ccel, fs, troll);
    gc_add_force(i, j, c, ccel, fs, troll);
  }
}

void PairTDEMGran::reset_dt()
{
  dt = update->dt;
}

int PairTDEMGran::pack_forward_comm(int n, int *list, double *buf, int /*pbc_flag*/, int * /*pbc*/)
{
  for (int i = 0; i < n; i++) buf[i] = rigid.mass[list[i]];
  return n;
}

void PairTDEMGran::unpack_forward_comm(int n, int first, double *buf)
{
  for (int i = 0; i < n; i++) rigid.mass[first + i] = buf[i];
}

double PairTDEMGran::memory_usage()
{
  return rigid.memory_usage();
}
