// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: pair style tdem/gran, the linear spring-dashpot normal law (tdem::lsd) with
// the Cundall-Strack tangential law (tdem::cundall_strack), per type pair.
//
//   pair_style tdem/gran [energy no|yes]
//   pair_coeff I J normal lsd stiffness KN GAMMAN tangential cundall_strack KT GAMMAT MU [options]
//   pair_coeff I J normal lsd restitution E TC tangential cundall_strack KAPPA MU [options]
//   pair_coeff I J normal hertz E NU [E2 NU2] [damping linear G|kuwabara_kono G|tsuji E|general TH C]
//                  tangential cundall_strack KAPPA MU [options]
//   pair_coeff I J normal walton_braun KL KUL [S] tangential cundall_strack KAPPA MU [options]
//   pair_coeff I J normal thornton E NU [E2 NU2] PY tangential cundall_strack KAPPA MU [options]
//   pair_coeff I J normal power_law AL P AUL [Q] tangential cundall_strack KAPPA MU [options]
//   pair_coeff I J normal extended_linear e_fit FORM C0 [C1 [C2]] tc_fit FORM C0 [C1]
//                  [v_min V] [v_max V] tangential cundall_strack KAPPA MU [options]
//   pair_coeff I J normal extended_hertz E NU [E2 NU2] e_fit FORM C0 [C1 [C2]] [v_min V] [v_max V]
//                  tangential cundall_strack KAPPA MU [options]
//   options: damping mass|absolute (lsd stiffness), limit_force no|yes, slip spring_dashpot|spring
//   energy yes: every contact accounts the work of its force parts (src/contact/energy.h) for
//   compute tdem/energy; a separate instantiation of the contact loop (energy no pays nothing)
//
// Derives from Pair and uses only FixNeighHistory and NeighRequest (not the GRANULAR classes),
// so the two files can be dropped into a LAMMPS src/ tree together with tdem_lammps_law.*,
// and src/contact/ from tdem. See docs/lammps.md.

#ifdef PAIR_CLASS
// clang-format off
PairStyle(tdem/gran,PairTDEMGran);
// clang-format on
#else

#ifndef TDEM_LMP_PAIR_TDEM_GRAN_H
#define TDEM_LMP_PAIR_TDEM_GRAN_H

#include "lammps_compat.h"
#include "pair.h"
#include "tdem_lammps_law.h"
#include "contact_host.h"

#include "clump_correction_host.h"
#include "grid_host.h"

#include "contact/energy.h"

#include <vector>

namespace LAMMPS_NS {

class PairTDEMGran : public Pair {
 public:
  PairTDEMGran(class LAMMPS *);
  ~PairTDEMGran() override;
  void compute(int, int) override;
  void settings(int, char **) override;
  void coeff(int, char **) override;
  void init_style() override;
  double init_one(int, int) override;
  double single(int, int, int, int, double, double, double, double &) override;
  void write_restart(FILE *) override;
  void read_restart(FILE *) override;
  void reset_dt() override;
  void transfer_history(TDEM_LMP_TRANSFER_HISTORY_PARAMS(, )) override;
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
  double memory_usage() override;
  TDEM_LMP_SIZE_CUT_OVERRIDES  // atom2cut, radii2cut where LAMMPS has them (lammps_compat.h)

  // evaluation body, instantiated per (mode, end, slip, tangential law) and ONE = 1 when every
  // type pair has the same coefficients (no per-type lookups); public for the dispatcher
  // (normal hertz with ONE: also the damping member D fixed); C = 1: the multiple-contact
  // correction of fix tdem/clump (its own instantiations, run-time law; C = 0 is the plain loop);
  // C = 2: the energy accounting (energy yes; run-time law)
  template <int M, int E, int S, int TL, int ONE = 0, int D = -1, int C = 0> void eval(int eflag, int vflag);

  // read-only view for other tdem styles (fix tdem/timestep): the law of type pair (i, j),
  // 1 <= i, j <= number of types (valid where setflag[i][j] or after init_one), and the
  // tangential law (TangentialLaw) of all type pairs
  const tdem_lammps::LawCoeffs &law_of(int i, int j) const { return law[i * (atom_ntypes + 1) + j]; }
  int tangential_law() const { return utlaw; }

  // energy yes: the energy the contacts took out of the motion per part (tdem::energy::Part) [J],
  // this rank's share: the ended contacts of its atoms and its share of the current ones (half of
  // a contact with a ghost partner when newton_pair is off). peratom (optional, rows of the
  // owned and ghost atoms, zeroed by the caller): half of every contact to each of its atoms; with
  // newton_pair on the caller folds the ghost rows into their owners.
  bool energy_enabled() const { return energy_on != 0; }
  void energy_sums(double *sums, double **peratom);
  // the current contacts of this rank, one row of kLocalColumns each (a contact with a ghost
  // partner on one rank only): the two atom IDs, the energy taken per part, their sum
  static constexpr int kLocalColumns = 2 + tdem::energy::kParts + 1;
  void energy_local(std::vector<double> &rows);

 protected:
  // error->one naming two atoms whose centres coincide (no contact normal); out of line and cold
  [[noreturn, gnu::cold, gnu::noinline]] void coincident_centres(int i, int j);

  double dt;
  int freeze_group_bit;
  int size_history;
  int neighprev;
  double *onerad_dynamic, *onerad_frozen;
  double *maxrad_dynamic, *maxrad_frozen;

  // per type pair coefficients, (ntypes+1)^2, symmetric
  std::vector<tdem_lammps::LawCoeffs> law;
  bool uniform;  // all set type pairs share mode, end and slip
  int umode, uend, uslip;
  int utlaw;  // the tangential law of all type pairs (TangentialLaw)
  bool one_law;  // every type pair has the same LawCoeffs (set by init_one of the last type pair)
  bool gc_any;   // some type pair has grid_correction on (its values end every history block)

  class FixNeighHistory *fix_history;
  std::string id_history, id_dummy;
  // how the restart file this pair was read from stores the neighbor-history partner IDs
  // (tdem_lammps::compat::HistoryTags; -2: not read from a restart file)
  int restart_history_tags;
  // history values per contact of the restart file this pair was read from (0: not read from one)
  int restart_history_size;

  tdem_lammps::RigidMasses rigid;  // body masses of the spheres of rigid bodies

  // multiple-contact correction of fix tdem/clump (clumps/multi_contact.h; count and overlap
  // tally the contacts another rank counts too with newton off)
  tdem_lammps::ClumpCorrection clump;

  void allocate();
  // energy yes: the per-atom store of the ended contacts' energy (fix TDEM/ENERGY/STORE)
  int energy_on;
  class FixTDEMEnergyStore *estore;
  std::string id_estore;
  void energy_end(int i, int j, double *slots, bool update);

  tdem_lammps::GcContact gc_pair_contact(int i, int j, const tdem_lammps::LawCoeffs &lw);
  void gc_add_force(int i, int j, const tdem_lammps::GcContact &c, double ccel, const double *fs,
                    const double *troll);
  template <int M, int E, int S, int TL, int D>
  void gc_deferred(const int *defer, int n, const tdem_lammps::LawCoeffs *one);
  std::vector<int> gc_defer;  // the contacts eval defers to gc_deferred (grid_correction)
  tdem_lammps::LawCoeffs &coeffs(int i, int j) { return law[i * (atom_ntypes + 1) + j]; }
  int atom_ntypes;
};

}  // namespace LAMMPS_NS

#endif
#endif
