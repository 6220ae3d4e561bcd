// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: registration table of the module 'timestep'.
#include "tdem_lammps_styles.h"

namespace tdem_lammps {

namespace {
const StyleEntry table[] = {{StyleKind::pair, nullptr, nullptr, nullptr}};
}  // namespace

const StyleEntry *timestep_styles()
{
  return table;
}

}  // namespace tdem_lammps
