// SPDX-License-Identifier: GPL-2.0-or-later
#include "tdem_liggghts_error.h"

#include <mpi.h>

#include <cstdio>
#include <cstdlib>

#include "atom.h"
#include "error.h"
#include "lammps.h"
#include "update.h"

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

void zero_distance_of_law(LAMMPS_NS::LAMMPS* lmp, const char* law, int i, int j, bool wall) {
  zero_distance(lmp, ("model tdem/" + std::string(law)).c_str(), i, j, wall);
}

void zero_distance(LAMMPS_NS::LAMMPS* lmp, const char* model, int i, int j, bool wall) {
  const auto tag = [lmp](int k) { return std::to_string(static_cast<long long>(lmp->atom->tag[k])); };
  const std::string step = std::to_string(static_cast<long long>(lmp->update->ntimestep));
  if (wall)
    error_one(lmp, __FILE__, __LINE__,
              std::string(model) + ": atom " + tag(i) + " has its centre on a wall surface (distance 0) at step " +
                  step + ": the contact normal is undefined; place the particle off the wall");
  error_one(lmp, __FILE__, __LINE__,
            std::string(model) + ": atoms " + tag(i) + " and " + tag(j) +
                " have coincident centres (distance 0) at step " + step +
                ": the contact normal is undefined; place the particles apart (e.g. delete_atoms overlap)");
}

}  // namespace liggghts
}  // namespace tdem
