// SPDX-License-Identifier: GPL-2.0-or-later
// tdem for LAMMPS: registration table of the module 'grate'.
#include "tdem_lammps_styles.h"

namespace tdem_lammps {

namespace {
const StyleEntry table[] = {{StyleKind::pair, nullptr, nullptr, nullptr}};
}  // namespace

const StyleEntry *grate_styles()
{
  return table;
}

}  // namespace tdem_lammps
