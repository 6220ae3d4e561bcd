// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: fix tdem/grate (see fix_tdem_grate.h and docs/lammps/fix_tdem_grate.md). The
// constructor (arguments and geometry) is in fix_tdem_grate_setup.cpp.

#include "fix_tdem_grate.h"

#include "contact/energy.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "memory.h"
#include "modify.h"
#include "respa.h"
#include "update.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <algorithm>
#include <cstring>
#include <stdexcept>

using namespace LAMMPS_NS;
using namespace FixConst;
namespace tg = tdem::grate;

FixTDEMGrate::~FixTDEMGrate()
{
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
  rigid.destroy(memory);
  extlist = nullptr;  // owned by extlist_store
}

int FixTDEMGrate::setmask()
{
  int mask = 0;
  mask |= POST_FORCE;
  mask |= POST_FORCE_RESPA;
  return mask;
}

double FixTDEMGrate::current_time() const
{
  return t_base + static_cast<double>(update->ntimestep - step_base) * dt_cur;
}

void FixTDEMGrate::rebase_time()
{
  // the time elapsed so far ran with dt_cur; continue with the new step from here
  if (update->dt == dt_cur) return;
  t_base = current_time();
  step_base = update->ntimestep;
  dt_cur = update->dt;
}

void FixTDEMGrate::init()
{
  rebase_time();
  if (utils::strmatch(update->integrate_style, "^respa"))
    nlevels_respa = ((Respa *) update->integrate)->nlevels;
  rigid.find(modify);
}

void FixTDEMGrate::reset_dt()
{
  rebase_time();
}

void FixTDEMGrate::setup(int vflag)
{
  tdem_lammps::setup_post_force(this, update, vflag, nlevels_respa);
}

void FixTDEMGrate::write_vtk(double t)
{
  if (comm->me != 0) return;
  try {
    if (!vtk_files)
      vtk_files = std::make_unique<tdem::vtkio::StepFiles>(vtk_prefix, tdem::vtkio::StepFiles::Kind::polydata);
    vtk_files->write(update->ntimestep, tg::bars_dataset(boxes_, t));
  } catch (const std::exception &ex) {
    error->one(FLERR, where + ": " + ex.what());
  }
}

namespace {
struct GrateRunner {
  FixTDEMGrate *f;
  template <int M, int E, int S, int TL = 0> void run() { f->template eval<M, E, S, TL>(); }
};
// the energy accounting: the law at run time, the tangential law at compile time
struct GrateRunnerEnergy {
  FixTDEMGrate *f;
  template <int M, int E, int S, int TL = 0> void run() { f->template eval<-1, -1, -1, TL, true>(); }
};
}  // namespace

void FixTDEMGrate::post_force(int /*vflag*/)
{
  // effective mass of a sphere of a rigid body: the body mass (as fix wall/gran)
  rigid.refresh(atom, memory, "tdem/grate:mass_rigid");

  const double t = current_time();
  t_last = t;
  const int wa = grate_->width_axis();
  const int periodic[3] = {domain->xperiodic, domain->yperiodic, domain->zperiodic};
  per_axis = periodic[wa] ? wa : -1;
  per_len = domain->prd[wa];
  boxes_ = grate_->boxes(t);
  force_flag = 0;
  fbar[0] = fbar[1] = fbar[2] = 0.0;
  if (energy_on)
    tdem_lammps::dispatch(false, law.mode, law.end, law.slip, law.tlaw, GrateRunnerEnergy{this});
  else
    tdem_lammps::dispatch(true, law.mode, law.end, law.slip, law.tlaw, GrateRunner{this});

  if (vtk_every && (update->setupflag || update->ntimestep % vtk_every == 0)) write_vtk(t);
}

namespace {
// One candidate contact of a sphere with a box.
struct Candidate {
  int box;
  double overlap;
  double n[3];  // unit normal from the box towards the sphere centre
  double q[3];  // contact point on the box surface
};

// Is p within the closed box b (enlarged by eps)?
inline bool within(const tg::Box &b, const double *p, double eps, int per_axis, double per_len)
{
  tg::Vec3 d{p[0] - b.centre.x, p[1] - b.centre.y, p[2] - b.centre.z};
  if (per_axis >= 0) d[per_axis] -= per_len * std::nearbyint(d[per_axis] / per_len);
  for (int k = 0; k < 3; ++k)
    if (std::fabs(tg::dot(d, b.axis[k])) > b.half[k] + eps) return false;
  return true;
}
}  // namespace

template <int M, int E, int S, int TL, bool EN>
__attribute__((flatten, noinline)) void FixTDEMGrate::eval()
{
  const bool history_update = !update->setupflag;
  const double dt = update->dt;

  const auto [x, v, f, omg, torque, radius, rmass, mask, nlocal] = tdem_lammps::sphere_arrays(atom);
  const int nbox = static_cast<int>(boxes_.size());
  // bounding box of the whole grate; the axes tested first are the non-periodic ones
  double all_lo[3], all_hi[3];
  for (int k = 0; k < 3; ++k) all_lo[k] = 1e300, all_hi[k] = -1e300;
  for (int b = 0; b < nbox; ++b)
    for (int k = 0; k < 3; ++k) {
      all_lo[k] = std::min(all_lo[k], boxes_[b].centre[k] - box_extent[3 * b + k]);
      all_hi[k] = std::max(all_hi[k], boxes_[b].centre[k] + box_extent[3 * b + k]);
    }
  const int ax_c = per_axis >= 0 ? per_axis : 2;  // tested last (after the minimum image)
  const int ax_a = ax_c == 0 ? 1 : 0;
  const int ax_b = 3 - ax_a - ax_c;

  std::vector<Candidate> cand;
  cand.reserve(nbox);
  std::vector<int> accepted;
  accepted.reserve(nbox);
  std::vector<char> used(max_contacts);

  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    const double rad = radius[i];
    const tg::Vec3 xi{x[i][0], x[i][1], x[i][2]};
    double *sl = rows_[i];

    // ---- candidate contacts: the bounding box of the whole grate first (an atom above the
    // bed's lowest layer stops here), then the bounding box of each box, then its closest point.
    // Along a periodic width axis the atom's image nearest to the box centre counts (bars with
    // lateral gaps reach across the periodic boundary).
    cand.clear();
    bool near = true;
    for (int k = 0; k < 3; ++k)
      if (k != per_axis && (xi[k] < all_lo[k] - rad || xi[k] > all_hi[k] + rad)) near = false;
    for (int b = 0; near && b < nbox; ++b) {
      const tg::Box &bx = boxes_[b];
      const double *ext = &box_extent[3 * b];  // half extents of the axis-aligned bounding box
      tg::Vec3 d = xi - bx.centre;
      if (std::fabs(d[ax_a]) > ext[ax_a] + rad || std::fabs(d[ax_b]) > ext[ax_b] + rad) continue;
      if (per_axis >= 0) d[per_axis] -= per_len * std::nearbyint(d[per_axis] / per_len);
      if (std::fabs(d[ax_c]) > ext[ax_c] + rad) continue;
      double s[3];
      bool inside = true, away = false;
      for (int k = 0; k < 3; ++k) {
        s[k] = tg::dot(d, bx.axis[k]);
        if (std::fabs(s[k]) > bx.half[k] + rad) away = true;
        if (std::fabs(s[k]) > bx.half[k]) inside = false;
      }
      if (away) continue;
      Candidate c;
      c.box = b;
      if (!inside) {
        // closest point of the box, relative to its centre; dq = centre of the sphere - it
        tg::Vec3 dq = d;
        for (int k = 0; k < 3; ++k) {
          const double sk = std::max(-bx.half[k], std::min(bx.half[k], s[k]));
          dq = dq - sk * bx.axis[k];
        }
        const double dist = tg::norm(dq);
        if (!(dist < rad) || dist <= 0.0) continue;
        c.overlap = rad - dist;
        c.n[0] = dq.x / dist, c.n[1] = dq.y / dist, c.n[2] = dq.z / dist;
        c.q[0] = xi.x - dq.x, c.q[1] = xi.y - dq.y, c.q[2] = xi.z - dq.z;
      } else {
        // centre inside the box (a broken state: far too deep): push out through the
        // nearest face
        int kmin = 0;
        double pmin = bx.half[0] - std::fabs(s[0]);
        for (int k = 1; k < 3; ++k) {
          const double pk = bx.half[k] - std::fabs(s[k]);
          if (pk < pmin) pmin = pk, kmin = k;
        }
        const double sg = s[kmin] >= 0.0 ? 1.0 : -1.0;
        const tg::Vec3 nn = sg * bx.axis[kmin];
        c.overlap = rad + pmin;
        c.n[0] = nn.x, c.n[1] = nn.y, c.n[2] = nn.z;
        const tg::Vec3 q = xi + pmin * nn;
        c.q[0] = q.x, c.q[1] = q.y, c.q[2] = q.z;
        if (ndeep++ == 0)
          error->warning(FLERR, where + ": the centre of atom " + std::to_string(atom->tag[i]) +
                                    " is inside a box at step " + std::to_string(update->ntimestep) +
                                    " (time step too large or bars too fast); pushed out through "
                                    "the nearest face (reported once per rank)");
      }
      cand.push_back(c);
    }

    if (cand.empty()) {  // no contact: free the slots still held
      for (int s = 0; s < max_contacts; ++s)
        if (sl[s * slot_size] >= 0.0) {
          if constexpr (EN) energy_free(i, sl + s * slot_size, history_update);
          sl[s * slot_size] = -1.0;
          for (int m = 1; m < slot_size; ++m) sl[s * slot_size + m] = 0.0;
        }
      continue;
    }

    // ---- accept in order of decreasing overlap; a contact point hidden inside a box already
    // accepted is not an exposed face (shared edges of neighbouring bars, roof-tile overlaps)
    for (size_t a = 1; a < cand.size(); ++a)
      for (size_t b = a; b > 0 && (cand[b].overlap > cand[b - 1].overlap ||
                                   (cand[b].overlap == cand[b - 1].overlap &&
                                    cand[b].box < cand[b - 1].box));
           --b)
        std::swap(cand[b], cand[b - 1]);
    accepted.clear();
    const double eps = 1e-9 * rad;
    for (size_t a = 0; a < cand.size(); ++a) {
      bool hidden = false;
      for (int acc : accepted)
        if (within(boxes_[cand[acc].box], cand[a].q, eps, per_axis, per_len)) {
          hidden = true;
          break;
        }
      if (!hidden) accepted.push_back(static_cast<int>(a));
    }

    // ---- history slots: keep those of the accepted boxes, free the others
    for (int s = 0; s < max_contacts; ++s) used[s] = 0;
    for (int acc : accepted) {
      const Candidate &c = cand[acc];
      int slot = -1;
      for (int s = 0; s < max_contacts; ++s)
        if (static_cast<int>(sl[s * slot_size]) == c.box) {
          slot = s;
          break;
        }
      if (slot < 0) {
        for (int s = 0; s < max_contacts; ++s)
          if (sl[s * slot_size] < 0.0 && !used[s]) {
            slot = s;
            break;
          }
        if (slot < 0)
          error->one(FLERR, where + ": atom " + std::to_string(atom->tag[i]) + " touches " +
                                std::to_string(accepted.size()) + " boxes at step " +
                                std::to_string(update->ntimestep) + ", more than max_contacts = " +
                                std::to_string(max_contacts) + "; increase max_contacts");
        sl[slot * slot_size] = c.box;
        for (int m = 1; m < slot_size; ++m) sl[slot * slot_size + m] = 0.0;
      }
      used[slot] = 1;
    }
    for (int s = 0; s < max_contacts; ++s)
      if (!used[s] && sl[s * slot_size] >= 0.0) {
        if constexpr (EN) energy_free(i, sl + s * slot_size, history_update);
        sl[s * slot_size] = -1.0;
        for (int m = 1; m < slot_size; ++m) sl[s * slot_size + m] = 0.0;
      }

    if (accepted.empty()) continue;
    const double meff = rigid.of(i, rmass[i]);

    // ---- forces, one contact per accepted box (a plane wall moving with the box)
    for (int acc : accepted) {
      const Candidate &c = cand[acc];
      const tg::Box &bx = boxes_[c.box];
      double *shear = nullptr;
      for (int s = 0; s < max_contacts; ++s)
        if (static_cast<int>(sl[s * slot_size]) == c.box) {
          shear = sl + s * slot_size + 1;
          break;
        }
      // del = centre - contact point, |del| = rad - overlap (kept positive for a centre that
      // sits inside a box; the forces depend on the direction of del and on the overlap only)
      const double r = std::max(rad - c.overlap, 1e-6 * rad);
      const double dx = c.n[0] * r, dy = c.n[1] * r, dz = c.n[2] * r;
      const double rinv = 1.0 / r;
      const double rsqinv = rinv * rinv;
      const double vr1 = v[i][0] - bx.velocity.x;
      const double vr2 = v[i][1] - bx.velocity.y;
      const double vr3 = v[i][2] - bx.velocity.z;
      const double wr1 = rad * omg[i][0] * rinv;
      const double wr2 = rad * omg[i][1] * rinv;
      const double wr3 = rad * omg[i][2] * rinv;

      double ccel, fs[3];
      [[maybe_unused]] tdem::NormalResult<double> nres{};
      tdem_lammps::evaluate_contact<M, E, S, TL>(law, meff, dx, dy, dz, r, rinv, rsqinv,
                                                 c.overlap, vr1, vr2, vr3, wr1, wr2, wr3, dt,
                                                 history_update, shear, ccel, fs, rad, 0.0, omg[i],
                                                 nullptr, nullptr, EN ? &nres : nullptr);
      if constexpr (EN) {
        // energy: the parts over the sphere's motion relative to the box, the box's work over its
        // own motion (as fix tdem/wall/gran energy yes); at set-up the loads only
        namespace en = tdem::energy;
        double *es = shear + law_history;
        const en::Compact<double> now =
            tdem_lammps::contact_loads(dx, dy, dz, rinv, ccel * r, nres.elastic, fs, rad, 0.0, nullptr);
        const double vb[3] = {bx.velocity.x, bx.velocity.y, bx.velocity.z};
        static const double rest[3] = {0.0, 0.0, 0.0};
        if (history_update)
          en::wall_step(es, now, en::pair_motion(v[i], vb, omg[i], rest, dt), vb, dt,
                        sl[max_contacts * slot_size + en::kParts]);
        else
          en::save(now, es);
      }
      double fw[3];
      tdem_lammps::add_wall_force(f[i], torque[i], dx, dy, dz, ccel, fs, rinv, rad, fw);
      fbar[0] -= fw[0];
      fbar[1] -= fw[1];
      fbar[2] -= fw[2];
    }
  }
}

// energy yes: the first step without the contact of slot (box index, history) of atom i: the last
// half step of its loads (relative to the box; the box's work over its own motion), then its
// energy to the row's tail (the caller frees the slot)
void FixTDEMGrate::energy_free(int i, double *slot, bool advance)
{
  namespace en = tdem::energy;
  double *es = slot + 1 + law_history;
  double *tail = rows_[i] + max_contacts * slot_size;
  if (advance && (es[0] != 0.0 || es[1] != 0.0 || es[2] != 0.0)) {
    const tdem::grate::Box &bx = boxes_[static_cast<int>(slot[0])];
    const double vb[3] = {bx.velocity.x, bx.velocity.y, bx.velocity.z};
    static const double rest[3] = {0.0, 0.0, 0.0};
    en::wall_step(es, en::Compact<double>{}, en::pair_motion(atom->v[i], vb, atom->omega[i], rest, update->dt), vb,
                  update->dt, tail[en::kParts]);
  }
  en::close(es, tail);
}

void FixTDEMGrate::energy_sums(double *parts, double *work, double **peratom, int wall_column) const
{
  namespace en = tdem::energy;
  if (!energy_on) return;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    const double *row = rows_[i], *tail = row + max_contacts * slot_size;
    for (int p = 0; p < en::kParts; p++) {
      double taken = tail[p];
      for (int s = 0; s < max_contacts; s++)
        if (row[s * slot_size] >= 0.0) taken -= row[s * slot_size + 1 + law_history + en::kCompactSize + p];
      parts[p] += taken;
      if (peratom) peratom[i][p] += taken;
    }
    *work += tail[en::kParts];
    if (peratom) peratom[i][wall_column] += tail[en::kParts];
  }
}

void FixTDEMGrate::post_force_respa(int vflag, int ilevel, int /*iloop*/)
{
  if (ilevel == nlevels_respa - 1) post_force(vflag);
}

double FixTDEMGrate::compute_vector(int n)
{
  if (n < 3) {
    if (!force_flag) {
      MPI_Allreduce(fbar, fbar_all, 3, MPI_DOUBLE, MPI_SUM, world);
      force_flag = 1;
    }
    return fbar_all[n];
  }
  // displacement u and velocity of phase group g at the last force evaluation
  const int g = (n - 3) / 2;
  const tg::MotionState m =
      tg::evaluate(grate_->params().motion, t_last, grate_->params().group_phase[g]);
  return ((n - 3) % 2 == 0) ? m.u : m.v;
}

void *FixTDEMGrate::extract(const char *name, int &dim)
{
  dim = 0;
  if (strcmp(name, "tdem_grate") == 0) return (void *) grate_.get();
  if (strcmp(name, "tdem_grate_time") == 0) return (void *) &t_last;
  return nullptr;
}

double FixTDEMGrate::memory_usage()
{
  return rows_memory() + rigid.memory_usage();
}

void FixTDEMGrate::set_arrays(int i)
{
  for (int s = 0; s < max_contacts; s++) {
    rows_[i][s * slot_size] = -1.0;
    for (int m = 1; m < slot_size; m++) rows_[i][s * slot_size + m] = 0.0;
  }
  for (int m = max_contacts * slot_size; m < width_; m++) rows_[i][m] = 0.0;  // energy: the tail
}

// global restart: the grate time origin and the layout of the per-atom slots
void FixTDEMGrate::write_restart(FILE *fp)
{
  if (comm->me != 0) return;
  double list[6] = {t_base, static_cast<double>(step_base), dt_cur,
                    static_cast<double>(boxes_.size()), static_cast<double>(size_history),
                    static_cast<double>(max_contacts)};
  int size = sizeof(list);
  fwrite(&size, sizeof(int), 1, fp);
  fwrite(list, sizeof(list), 1, fp);
}

void FixTDEMGrate::restart(char *buf)
{
  const double *list = (const double *) buf;
  t_base = list[0];
  step_base = static_cast<bigint>(list[1]);
  dt_cur = list[2];
  const int nbox = static_cast<int>(list[3]);
  const int hs = static_cast<int>(list[4]);
  if (nbox != static_cast<int>(boxes_.size()) || hs != size_history)
    error->all(FLERR, where + ": the restart file holds contact histories of " +
                          std::to_string(nbox) + " boxes with " + std::to_string(hs) +
                          " history values each, this fix has " + std::to_string(boxes_.size()) +
                          " boxes with " + std::to_string(size_history) +
                          "; define the grate and the law as before the restart (or use a new fix ID)");
}

void FixTDEMGrate::unpack_restart(int nlocal, int nth)
{
  const double *rec = tdem::host::restart_record(atom->extra, nlocal, nth);
  const int count = static_cast<int>(rec[0]) - 1;
  set_arrays(nlocal);
  // the stored number of slots may differ from max_contacts: keep the occupied ones
  const int stored = count / slot_size;
  int k = 0;
  for (int s = 0; s < stored; s++) {
    const double *src = &rec[1 + s * slot_size];
    if (src[0] < 0.0) continue;
    if (k >= max_contacts)
      error->one(FLERR, where + ": atom " + std::to_string(atom->tag[nlocal]) +
                            " has more contacts in the restart file than max_contacts = " +
                            std::to_string(max_contacts));
    for (int q = 0; q < slot_size; q++) rows_[nlocal][k * slot_size + q] = src[q];
    ++k;
  }
  // energy yes: the tail after the slots (the ended contacts' energy, the bars' work)
  const int tail = width_ - max_contacts * slot_size;
  if (tail > 0 && count - stored * slot_size == tail)
    for (int q = 0; q < tail; q++) rows_[nlocal][max_contacts * slot_size + q] = rec[1 + stored * slot_size + q];
}

