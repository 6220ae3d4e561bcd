// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: pair style tdem/gran, its set-up: pair_style and pair_coeff arguments, the
// neighbour list and history fix, the per-type-pair coefficients and cutoffs, and restart.
// The contact loop is in pair_tdem_gran.cpp.

#include "pair_tdem_gran.h"

#include "fix_tdem_energy_store.h"

#include "contact/energy.h"

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
#include <cstdio>
#include <cstring>

using namespace LAMMPS_NS;
using tdem_lammps::LawCoeffs;

/* ---------------------------------------------------------------------- */
void PairTDEMGran::allocate()
{
  allocated = 1;
  const int n = atom->ntypes;
  atom_ntypes = n;

  memory->create(setflag, n + 1, n + 1, "pair:setflag");
  for (int i = 1; i <= n; i++)
    for (int j = i; j <= n; j++) setflag[i][j] = 0;
  memory->create(cutsq, n + 1, n + 1, "pair:cutsq");

  onerad_dynamic = new double[n + 1];
  onerad_frozen = new double[n + 1];
  maxrad_dynamic = new double[n + 1];
  maxrad_frozen = new double[n + 1];
  law.assign((size_t) (n + 1) * (n + 1), LawCoeffs());
}

/* ---------------------------------------------------------------------- */

void PairTDEMGran::settings(int narg, char **arg)
{
  // pair_style tdem/gran [energy no|yes]; the law goes into pair_coeff
  int on = 0;
  for (int a = 0; a < narg; a += 2) {
    if (std::strcmp(arg[a], "energy") != 0)
      error->all(FLERR, std::string("pair_style tdem/gran: unknown keyword '") + arg[a] +
                            "' (it takes only 'energy no|yes'; the law goes into pair_coeff)");
    if (a + 1 >= narg) error->all(FLERR, "pair_style tdem/gran: energy needs a value, no or yes");
    if (std::strcmp(arg[a + 1], "yes") == 0)
      on = 1;
    else if (std::strcmp(arg[a + 1], "no") == 0)
      on = 0;
    else
      error->all(FLERR, std::string("pair_style tdem/gran: energy takes no or yes, got '") + arg[a + 1] + "'");
  }
  if (fix_history && on != energy_on)
    error->all(FLERR, "pair_style tdem/gran: energy cannot be switched after a run (the contacts' "
                      "history has another size); use clear, or set it from the start");
  energy_on = on;
}

/* ---------------------------------------------------------------------- */

void PairTDEMGran::coeff(int narg, char **arg)
{
  if (narg < 2)
    error->all(FLERR, "pair_coeff tdem/gran: needs I J normal lsd ... tangential cundall_strack ...");
  if (!allocated) allocate();

  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);

  const std::string where = std::string("pair_coeff ") + arg[0] + " " + arg[1] + " (tdem/gran)";
  LawCoeffs c;
  tdem_lammps::parse_law(lmp, where, narg, arg, 2, false, c);

  int count = 0;
  for (int i = ilo; i <= ihi; i++) {
    for (int j = MAX(jlo, i); j <= jhi; j++) {
      coeffs(i, j) = c;
      coeffs(j, i) = c;
      setflag[i][j] = 1;
      count++;
    }
  }
  if (count == 0)
    error->all(FLERR, where + ": the type range selects no type pair (I <= J is required)");
}

/* ---------------------------------------------------------------------- */

void PairTDEMGran::init_style()
{
  if (!atom->radius_flag || !atom->rmass_flag)
    error->all(FLERR, "pair tdem/gran requires atom attributes radius, rmass (atom_style sphere)");
  if (comm->ghost_velocity == 0)
    error->all(FLERR, "pair tdem/gran requires ghost atoms store velocity: use comm_modify vel yes");

  // a size neighbour list with history
  tdem_lammps::compat::request_size_list(neighbor, this, instance_me, true);

  dt = update->dt;

  // one tangential law for all type pairs (the history layout and its transfer depend on it)
  utlaw = -1;
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      if (!setflag[i][j]) continue;
      const int t = coeffs(i, j).tlaw;
      if (utlaw < 0) utlaw = t;
      else if (t != utlaw)
        error->all(FLERR, std::string("pair tdem/gran: tangential law '") + tdem_lammps::tangential_name(t) +
                              "' of type pair " + std::to_string(i) + " " + std::to_string(j) +
                              " differs from '" + tdem_lammps::tangential_name(utlaw) +
                              "' of another type pair; all type pairs must use the same tangential law");
    }
  if (utlaw < 0) utlaw = tdem_lammps::TLAW_CUNDALL_STRACK;

  // history values per neighbour: the tangential block + the largest normal-law need
  int need_history = tdem_lammps::tangential_history_size(utlaw);
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++)
      if (setflag[i][j])
        need_history = MAX(need_history, tdem_lammps::law_history_size(coeffs(i, j), utlaw));
  // energy yes: the accounting's slots end every contact's history (after the correction's)
  if (energy_on) need_history += tdem::energy::kSlots;
  if (fix_history == nullptr && restart_history_size > 0 && need_history != restart_history_size)
    error->all(FLERR,
               "pair tdem/gran: the contacts of the restart file have " + std::to_string(restart_history_size) +
                   " history values each, but the pair_coeff laws now need " + std::to_string(need_history) +
                   "; a law with a different history size (grid_correction, rolling, walton_braun, thornton, "
                   "power_law, the extended laws, another tangential law) cannot take over the contacts of a "
                   "restart file (keep the restart's law, or start from a data file: write_data and read_data "
                   "drop the contact history)");
  if (fix_history == nullptr)
    size_history = need_history;
  else if (need_history != size_history)
    error->all(FLERR,
               "pair tdem/gran: the pair_coeff laws now need " + std::to_string(need_history) +
                   " history values per contact, but the history was created with " +
                   std::to_string(size_history) +
                   "; changing to a law with a different history size (walton_braun, thornton, "
                   "power_law, extended_linear, extended_hertz, or another tangential law) after a "
                   "run is not supported "
                   "(use clear, or define that law from the start)");
  // grid_correction on for some type pair: its flags are the last value of every contact's history
  gc_any = false;
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++)
      if (setflag[i][j] && coeffs(i, j).gc) gc_any = true;
  // the tangential spring flips sign with the pair order, xi_max does not (the correction's flags
  // are read whatever their sign: LAMMPS's default, which negates all, keeps them)
  nondefault_history_transfer =
      (size_history - (gc_any ? tdem::grid::history_size : 0) > tdem_lammps::TANGENTIAL_HISTORY ||
       utlaw != tdem_lammps::TLAW_CUNDALL_STRACK || energy_on)
          ? 1
          : 0;
  // energy yes and grid_correction: a contact that ends at a step that rebuilds the neighbour list
  // keeps its history (FixNeighHistory drops the history of pairs apart at the rebuild unless
  // beyond_contact), so that its last half step and its work reach the store, and the end's
  // impulse of the correction is applied
  beyond_contact = (energy_on || gc_any) ? 1 : 0;
  if (energy_on && gc_any)
    error->all(FLERR, "pair tdem/gran: energy yes with grid_correction on is not supported in LAMMPS yet "
                      "(tdem-collide --energy on accounts the correction's force); turn one of them off");

  // on first init replace the placeholder with the FixNeighHistory that stores the history.
  // A restart file from another LAMMPS generation may store the history partners' IDs in the
  // other encoding (lammps_compat.h): they are rewritten before the fix reads them.
  if (fix_history == nullptr && restart_history_tags != -2) {
    namespace cp = tdem_lammps::compat;
    const auto from = (cp::HistoryTags) restart_history_tags;
    if (cp::history_tags() == cp::HistoryTags::unknown && from != cp::HistoryTags::unknown)
      error->all(FLERR, "pair tdem/gran: cannot tell how this LAMMPS stores neighbor-history partner IDs "
                        "in restart files (its fix_neigh_history.cpp was not seen when tdem was built), so "
                        "the contact history of this restart file cannot be read safely; build tdem "
                        "against the full LAMMPS source tree (LAMMPS_HEADER_DIR=<lammps>/src)");
    if (from == cp::HistoryTags::unknown && cp::history_tags() != cp::HistoryTags::unknown)
      error->all(FLERR, "pair tdem/gran: the restart file was written by a tdem build that could not tell "
                        "how its LAMMPS stored neighbor-history partner IDs; continue it with that build");
    const long n = cp::convert_history_restart_tags(modify, atom, id_history, "NEIGH_HISTORY", size_history,
                                                    from, cp::history_tags());
    if (n > 0 && comm->me == 0)
      utils::logmesg(lmp, "pair tdem/gran: the restart file stores neighbor-history partner IDs as " +
                              std::string(from == cp::HistoryTags::value ? "values (LAMMPS up to 2022)"
                                                                         : "integer bits (LAMMPS since 2023)") +
                              "; " + std::to_string(n) + " IDs on rank 0 converted for this LAMMPS\n");
  }
  if (fix_history == nullptr) {
    const std::string cmd = id_history + " all NEIGH_HISTORY " + std::to_string(size_history);
    fix_history = (FixNeighHistory *) modify->replace_fix(id_dummy, cmd, 1);
    fix_history->pair = this;
  }

  // fix freeze: frozen particles have infinite mass
  const Fix *freeze = tdem_lammps::compat::first_fix_by_style(modify, "^freeze");
  freeze_group_bit = freeze ? freeze->groupbit : 0;

  // fix rigid: use body masses (first rigid fix, as the LAMMPS granular styles)
  rigid.find(modify);

  // largest radii per type, including particles fix pour / fix deposit will insert
  Fix *pour = tdem_lammps::compat::first_fix_by_style(modify, "^pour");
  Fix *deposit = tdem_lammps::compat::first_fix_by_style(modify, "^deposit");
  for (int i = 1; i <= atom->ntypes; i++) {
    onerad_dynamic[i] = onerad_frozen[i] = 0.0;
    int itype = i;
    if (pour) onerad_dynamic[i] = *((double *) pour->extract("radius", itype));
    itype = i;
    if (deposit) onerad_dynamic[i] = *((double *) deposit->extract("radius", itype));
  }
  double *radius = atom->radius;
  int *mask = atom->mask;
  int *type = atom->type;
  const int nlocal = atom->nlocal;
  for (int i = 0; i < nlocal; i++) {
    if (mask[i] & freeze_group_bit)
      onerad_frozen[type[i]] = MAX(onerad_frozen[type[i]], radius[i]);
    else
      onerad_dynamic[type[i]] = MAX(onerad_dynamic[type[i]], radius[i]);
  }
  MPI_Allreduce(&onerad_dynamic[1], &maxrad_dynamic[1], atom->ntypes, MPI_DOUBLE, MPI_MAX, world);
  MPI_Allreduce(&onerad_frozen[1], &maxrad_frozen[1], atom->ntypes, MPI_DOUBLE, MPI_MAX, world);
  // fix tdem/clump with a multiple-contact correction: the corrected path (the largest overlap is
  // below the largest diameter)
  double dmax = 0.0;
  for (int i = 1; i <= atom->ntypes; i++) dmax = MAX(dmax, 2.0 * MAX(maxrad_dynamic[i], maxrad_frozen[i]));
  clump.find(lmp, "pair tdem/gran", dmax);
  if (energy_on && clump.mode != 0)
    error->all(FLERR, "pair tdem/gran: energy yes with the multiple-contact correction of fix tdem/clump "
                      "is not supported yet; use correction none, or energy no");

  // energy yes: the per-atom store of the ended contacts' energy (restart: the same ID picks up
  // the values of the restart file)
  if (energy_on && !estore) {
    estore = (FixTDEMEnergyStore *) modify->add_fix(id_estore + " all TDEM/ENERGY/STORE", 1);
  }

  const int ifix = modify->find_fix(id_history);
  if (ifix < 0) error->all(FLERR, "pair tdem/gran: could not find its fix " + id_history);
  fix_history = (FixNeighHistory *) modify->fix[ifix];

  // compile-time specialisation when every type pair uses the same variant
  one_law = false;  // decided by init_one of the last type pair
  uniform = true;
  bool first = true;
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      if (!setflag[i][j]) continue;
      const LawCoeffs &c = coeffs(i, j);
      if (first) {
        umode = c.mode;
        uend = c.end;
        uslip = c.slip;
        first = false;
      } else if (c.mode != umode || c.end != uend || c.slip != uslip) {
        uniform = false;
      }
    }
}

/* ---------------------------------------------------------------------- */

double PairTDEMGran::init_one(int i, int j)
{
  if (!allocated) allocate();
  if (!setflag[i][j] && setflag[i][i] && setflag[j][j] &&
      tdem_lammps::mixes_materials(coeffs(i, i).mode) && coeffs(j, j).mode == coeffs(i, i).mode) {
    // normal hertz mixes the materials: 1/E* = (1-nu_i^2)/E_i + (1-nu_j^2)/E_j, with the
    // material of type I from pair_coeff I I and of type J from pair_coeff J J; everything
    // else (damping, tangential law, options) must agree
    const LawCoeffs &a = coeffs(i, i), &b = coeffs(j, j);
    bool own_differ = false;  // a unit's own values (after its materials)
    for (int k = tdem::law::MATERIAL_VALUES; k < tdem::law::MAX_UNIT_VALUES; ++k) own_differ |= a.uv[k] != b.uv[k];
    if (a.hdamp != b.hdamp || a.hgamma != b.hgamma || a.htheta != b.htheta || a.he != b.he || own_differ ||
        (a.mode == tdem_lammps::MODE_EXT_HERTZ &&
         (a.ext.e_fit.form != b.ext.e_fit.form || a.ext.e_fit.c[0] != b.ext.e_fit.c[0] ||
          a.ext.e_fit.c[1] != b.ext.e_fit.c[1] || a.ext.e_fit.c[2] != b.ext.e_fit.c[2] ||
          a.ext.range.v_min != b.ext.range.v_min || a.ext.range.v_max != b.ext.range.v_max)) ||
        a.kappa != b.kappa || a.mu != b.mu || a.end != b.end || a.slip != b.slip ||
        a.tlaw != b.tlaw || a.tlimit != b.tlimit || a.t_kt != b.t_kt || a.t_kappa != b.t_kappa ||
        a.t_gammat != b.t_gammat || a.t_mu != b.t_mu || a.t_ratio != b.t_ratio)
      error->all(FLERR,
                 "pair tdem/gran: no pair_coeff for type pair " + std::to_string(i) + " " +
                     std::to_string(j) +
                     " and the normal " + tdem_lammps::material_law_names() +
                     " laws (with their tangential "
                     "laws) of types I I and J J differ in more than the materials (E, NU); set "
                     "this type pair");
    LawCoeffs c = a;
    c.E2 = b.E1;
    c.nu2 = b.nu1;
    if (tdem_lammps::is_unit(c.mode)) c.uv[2] = b.uv[0], c.uv[3] = b.uv[1];  // E2 NU2 of a unit
    c.tE2 = b.tE1;  // Mindlin-type tangential laws: G* of the two materials
    c.tnu2 = b.tnu1;
    tdem_lammps::derive_law(lmp, "pair tdem/gran (mixing types " + std::to_string(i) + " " +
                                     std::to_string(j) + ")", c);
    coeffs(i, j) = c;
    coeffs(j, i) = c;
  } else if (!setflag[i][j])
    error->all(FLERR,
               "pair tdem/gran: no pair_coeff for type pair " + std::to_string(i) + " " +
                   std::to_string(j) + " (this style has no mixing rule; set every type pair)");
  coeffs(j, i) = coeffs(i, j);

  // Pair::init calls init_one for every I <= J, the last type pair last: then all coefficients
  // are known. Bytewise equal LawCoeffs (a conservative test: padding may differ) let compute()
  // skip the per-type lookups.
  if (i == atom->ntypes && j == atom->ntypes) {
    one_law = true;
    for (int a = 1; a <= atom->ntypes && one_law; a++)
      for (int b = 1; b <= atom->ntypes; b++)
        if (std::memcmp(&coeffs(a, b), &coeffs(1, 1), sizeof(LawCoeffs)) != 0) {
          one_law = false;
          break;
        }
  }

  // cutoff = sum of the largest I,J radii, dynamic/dynamic and dynamic/frozen
  double cutoff = maxrad_dynamic[i] + maxrad_dynamic[j];
  cutoff = MAX(cutoff, maxrad_frozen[i] + maxrad_dynamic[j]);
  cutoff = MAX(cutoff, maxrad_dynamic[i] + maxrad_frozen[j]);
  return cutoff;
}

/* ----------------------------------------------------------------------
   one pair (compute pair/local etc.): force over distance, no history update
------------------------------------------------------------------------- */

double PairTDEMGran::single(int i, int j, int itype, int jtype, double rsq, double /*factor_coul*/,
                            double /*factor_lj*/, double &fforce)
{
  double *radius = atom->radius;
  const double radi = radius[i], radj = radius[j];
  const double radsum = radi + radj;
  for (int m = 0; m < single_extra; m++) svector[m] = 0.0;
  fforce = 0.0;
  if (rsq >= radsum * radsum) return 0.0;
  if (rsq == 0.0) coincident_centres(i, j);

  double **x = atom->x;
  double **v = atom->v;
  double **omega = atom->omega;
  const double delx = x[i][0] - x[j][0];
  const double dely = x[i][1] - x[j][1];
  const double delz = x[i][2] - x[j][2];
  const double r = sqrt(rsq);
  const double rinv = 1.0 / r;
  const double rsqinv = 1.0 / rsq;
  const double vr1 = v[i][0] - v[j][0];
  const double vr2 = v[i][1] - v[j][1];
  const double vr3 = v[i][2] - v[j][2];
  const double wr1 = (radi * omega[i][0] + radj * omega[j][0]) * rinv;
  const double wr2 = (radi * omega[i][1] + radj * omega[j][1]) * rinv;
  const double wr3 = (radi * omega[i][2] + radj * omega[j][2]) * rinv;

  double *rmass = atom->rmass;
  int *mask = atom->mask;
  const double mi = rigid.of(i, rmass[i]), mj = rigid.of(j, rmass[j]);
  double meff = mi * mj / (mi + mj);
  if (mask[i] & freeze_group_bit) meff = mj;
  if (mask[j] & freeze_group_bit) meff = mi;

  // the stored history of this pair (searched from the previous hit); a copy, not updated
  double shear[tdem_lammps::MAX_HISTORY] = {};
  const int jnum = list->numneigh[i];
  int *jlist = list->firstneigh[i];
  for (int jj = 0; jj < jnum; jj++) {
    neighprev++;
    if (neighprev >= jnum) neighprev = 0;
    if ((jlist[neighprev] & NEIGHMASK) == j) {
      const double *h = &fix_history->firstvalue[i][size_history * neighprev];
      for (int m = 0; m < size_history && m < tdem_lammps::MAX_HISTORY; m++) shear[m] = h[m];
      break;
    }
  }

  double ccel, fs[3];
  if (coeffs(itype, jtype).tlaw == tdem_lammps::TLAW_CUNDALL_STRACK)
    tdem_lammps::evaluate_contact<-1, -1, -1>(coeffs(itype, jtype), meff, delx, dely, delz, r, rinv,
                                              rsqinv, radsum - r, vr1, vr2, vr3, wr1, wr2, wr3, dt,
                                              false, shear, ccel, fs, radi, radj);
  else
    tdem_lammps::evaluate_contact<-1, -1, -1, -1>(coeffs(itype, jtype), meff, delx, dely, delz, r,
                                                  rinv, rsqinv, radsum - r, vr1, vr2, vr3, wr1, wr2,
                                                  wr3, dt, false, shear, ccel, fs, radi, radj,
                                                  omega[i], omega[j]);
  fforce = ccel;
  const double vnnr = vr1 * delx + vr2 * dely + vr3 * delz;
  svector[0] = fs[0];
  svector[1] = fs[1];
  svector[2] = fs[2];
  svector[3] = sqrt(fs[0] * fs[0] + fs[1] * fs[1] + fs[2] * fs[2]);
  svector[4] = delx * vnnr * rsqinv;
  svector[5] = dely * vnnr * rsqinv;
  svector[6] = delz * vnnr * rsqinv;
  svector[7] = vr1 - svector[4];
  svector[8] = vr2 - svector[5];
  svector[9] = vr3 - svector[6];
  return 0.0;
}

/* ---------------------------------------------------------------------- */

// Restart data: a version number, then per type pair I <= J the setflag and, if set, the
// LawCoeffs bytes. Version 3 (power_law, extended_linear, extended_hertz) and version 4 (the
// tangential laws other than cundall_strack) appended members to LawCoeffs; version 2 and 3
// files hold the first LAW_COEFFS_V2_SIZE / LAW_COEFFS_V3_SIZE bytes and are still read.
// Version 5 adds, after the version, how the writing LAMMPS stores neighbor-history partner IDs
// (compat::HistoryTags); files of versions 2-4 were written by tdem on LAMMPS 2022 (values).
// Version 6 appends the rolling resistance (LawCoeffs::roll, rp); versions 4 and 5 hold
// LAW_COEFFS_V5_SIZE bytes. Version 7 stores the normal law's name (RESTART_NAME bytes) before
// the LawCoeffs of each type pair, and the values of a unit law (LawCoeffs::uv): the reader takes
// the law by its name and derives its parameters anew. Version 8 appends grid_correction
// (LawCoeffs::gc); version 7 files hold LAW_COEFFS_V7_SIZE bytes. In files of versions 2-6 walton_braun,
// thornton and power_law were modes 4-6 with members of their own (read_legacy_units).
static constexpr int RESTART_NAME = 32;

void PairTDEMGran::write_restart(FILE *fp)
{
  const int version = 9;
  fwrite(&version, sizeof(int), 1, fp);
  const int tags = (int) tdem_lammps::compat::history_tags();
  fwrite(&tags, sizeof(int), 1, fp);
  fwrite(&energy_on, sizeof(int), 1, fp);
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      fwrite(&setflag[i][j], sizeof(int), 1, fp);
      if (!setflag[i][j]) continue;
      char name[RESTART_NAME] = {};
      std::snprintf(name, sizeof name, "%s", tdem_lammps::normal_name(coeffs(i, j)));
      fwrite(name, 1, sizeof name, fp);
      fwrite(&coeffs(i, j), sizeof(LawCoeffs), 1, fp);
    }
}

void PairTDEMGran::read_restart(FILE *fp)
{
  allocate();
  const int me = comm->me;
  int version = 0;
  if (me == 0) utils::sfread(FLERR, &version, sizeof(int), 1, fp, nullptr, error);
  MPI_Bcast(&version, 1, MPI_INT, 0, world);
  if (version < 2 || version > 9)
    error->all(FLERR, "pair tdem/gran: restart data of version " + std::to_string(version) +
                          " cannot be read (this build reads versions 2 to 9)");
  int tags = (int) tdem_lammps::compat::HistoryTags::value;  // versions 2-4: LAMMPS 2022
  if (version >= 5) {
    if (me == 0) utils::sfread(FLERR, &tags, sizeof(int), 1, fp, nullptr, error);
    MPI_Bcast(&tags, 1, MPI_INT, 0, world);
  }
  restart_history_tags = tags;
  energy_on = 0;  // version 9: pair_style tdem/gran energy
  if (version >= 9) {
    if (me == 0) utils::sfread(FLERR, &energy_on, sizeof(int), 1, fp, nullptr, error);
    MPI_Bcast(&energy_on, 1, MPI_INT, 0, world);
  }
  restart_history_size = 0;  // set below from the laws read
  const size_t nbytes = version >= 8   ? sizeof(LawCoeffs)
                        : version == 7 ? tdem_lammps::LAW_COEFFS_V7_SIZE
                        : version == 6 ? tdem_lammps::LAW_COEFFS_V6_SIZE
                        : version >= 4 ? tdem_lammps::LAW_COEFFS_V5_SIZE
                        : version == 3 ? tdem_lammps::LAW_COEFFS_V3_SIZE
                                       : tdem_lammps::LAW_COEFFS_V2_SIZE;
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      if (me == 0) utils::sfread(FLERR, &setflag[i][j], sizeof(int), 1, fp, nullptr, error);
      MPI_Bcast(&setflag[i][j], 1, MPI_INT, 0, world);
      if (setflag[i][j]) {
        LawCoeffs c;
        char name[RESTART_NAME] = {};
        if (me == 0 && version >= 7) utils::sfread(FLERR, name, 1, sizeof name, fp, nullptr, error);
        if (me == 0) utils::sfread(FLERR, &c, nbytes, 1, fp, nullptr, error);
        MPI_Bcast(name, sizeof name, MPI_CHAR, 0, world);
        MPI_Bcast(&c, nbytes, MPI_BYTE, 0, world);
        name[RESTART_NAME - 1] = '\0';
        if (version >= 7) {
          const int mode = tdem_lammps::mode_of_name(name, c.mode);
          if (mode < 0)
            error->all(FLERR, std::string("pair tdem/gran: the restart file holds normal law '") + name +
                                  "' for type pair " + std::to_string(i) + " " + std::to_string(j) +
                                  ", which this build does not have");
          c.mode = mode;
        } else {
          tdem_lammps::read_legacy_units(c);
        }
        if (tdem_lammps::is_unit(c.mode))
          tdem_lammps::derive_law(lmp, "pair tdem/gran (restart, type pair " + std::to_string(i) + " " +
                                           std::to_string(j) + ")", c);
        coeffs(i, j) = c;
        coeffs(j, i) = c;
      }
    }
  // the history values per contact the restart file's contacts carry (as init_style sizes them)
  int tl = -1;
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++)
      if (setflag[i][j] && tl < 0) tl = coeffs(i, j).tlaw;
  if (tl < 0) tl = tdem_lammps::TLAW_CUNDALL_STRACK;
  restart_history_size = tdem_lammps::tangential_history_size(tl);
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++)
      if (setflag[i][j])
        restart_history_size = MAX(restart_history_size, tdem_lammps::law_history_size(coeffs(i, j), tl));
  if (energy_on) restart_history_size += tdem::energy::kSlots;
}
