// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: the per-atom store of the energy accounting of pair tdem/gran (energy yes).
// Internal: the pair style creates it (style TDEM/ENERGY/STORE, as it creates its NEIGH_HISTORY);
// it is not an input-script command.
//
// Each atom keeps the energy the ended contacts it took part in took out of the motion, per part
// of the force (tdem::energy::Part), half of every contact's to each of its two atoms: a row of
// tdem::host::PerAtomRows, which moves with its atom between ranks and goes into restart files with
// it. A contact that ends on a rank where its partner is a ghost (newton_pair on) adds the
// partner's half to the ghost's row; fold() then sends the ghost rows to their owners (reverse
// communication) and clears them.

#ifdef FIX_CLASS
// clang-format off
FixStyle(TDEM/ENERGY/STORE,FixTDEMEnergyStore);
// clang-format on
#else

#ifndef TDEM_LMP_FIX_TDEM_ENERGY_STORE_H
#define TDEM_LMP_FIX_TDEM_ENERGY_STORE_H

#include "fix.h"
#include "pair_styles/per_atom_rows.h"

#include "contact/energy.h"

namespace LAMMPS_NS {

class FixTDEMEnergyStore : public tdem::host::PerAtomRows<Fix> {
 public:
  static constexpr int kValues = tdem::energy::kParts;
  FixTDEMEnergyStore(class LAMMPS *, int, char **);
  ~FixTDEMEnergyStore() override;
  int setmask() override { return 0; }
  int pack_reverse_comm(int, int, double *) override;
  void unpack_reverse_comm(int, int *, double *) override;
  double memory_usage() override { return rows_memory(); }

  // the row of atom i (owned or ghost) [J], one value per part
  double *row(int i) { return rows_[i]; }
  // before a contact loop: the ghost rows are zero (and as many as the atoms have)
  void clear_ghosts();
  // after it: the ghost rows added to their owners' (newton_pair on), then zero
  void fold();
};

}  // namespace LAMMPS_NS

#endif
#endif
