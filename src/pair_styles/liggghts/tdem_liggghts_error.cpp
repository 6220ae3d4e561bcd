// SPDX-License-Identifier: GPL-2.0-or-later
#include "tdem_liggghts_error.h"

#include <mpi.h>

#include <cstdio>
#include <cstdlib>

#include "error.h"
#include "lammps.h"

namespace tdem {
namespace liggghts {

void error_one(LAMMPS_NS::LAMMPS* lmp, const char* file, int line, const std::string& msg) {
  int me = 0;
  MPI_Comm_rank(lmp->world, &me);
  if (lmp->logfile) {
    std::fprintf(lmp->logfile, "ERROR on proc %d: %s (%s:%d)\n", me, msg.c_str(), file, line);
    std::fflush(lmp->logfile);
  }
  if (lmp->screen) {
    std::fflush(lmp->screen);
    std::setvbuf(lmp->screen, nullptr, _IONBF, 0);  // so error->one's line reaches the screen
  }
  lmp->error->one(file, line, msg.c_str());
  std::abort();  // not reached: error->one aborts
}

}  // namespace liggghts
}  // namespace tdem
