// SPDX-License-Identifier: GPL-2.0-or-later
// tdem-liggghts: a drop-in for the `liggghts` executable (same command line: -in, -var, -log,
// -echo, -screen, ...) with the tdem contact laws registered before the LAMMPS instance is
// created. Everything else is what LIGGGHTS's own main program does. With -h / -help, LIGGGHTS
// prints its compiled style lists and exits inside the constructor; tdem's models and styles follow
// them (an exit handler, rank 0).
#include <mpi.h>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "input.h"
#include "lammps.h"
#include "signal_handling.h"

#include "tdem_liggghts.h"

int main(int argc, char** argv) {
  struct sigaction int_action, usr1_action;
  std::memset(&int_action, 0, sizeof int_action);
  std::memset(&usr1_action, 0, sizeof usr1_action);
  int_action.sa_handler = LAMMPS_NS::SignalHandler::int_handler;
  sigaction(SIGINT, &int_action, nullptr);
  sigaction(SIGTERM, &int_action, nullptr);  // Open MPI turns SIGINT to mpirun into SIGTERM
  usr1_action.sa_handler = LAMMPS_NS::SignalHandler::usr1_handler;
  sigaction(SIGUSR1, &usr1_action, nullptr);

  MPI_Init(&argc, &argv);
  tdem::liggghts::register_styles();
  int me = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &me);
  for (int i = 1; i < argc && me == 0; i++)
    if (std::strcmp(argv[i], "-h") == 0 || std::strcmp(argv[i], "-help") == 0) {
      std::atexit([] { std::fputs(tdem::liggghts::style_listing().c_str(), stdout); });
      break;
    }

  LAMMPS_NS::LAMMPS* lammps = new LAMMPS_NS::LAMMPS(argc, argv, MPI_COMM_WORLD);
  tdem::liggghts::attach(lammps);
  lammps->input->file();
  tdem::liggghts::attach(nullptr);
  delete lammps;

  MPI_Finalize();
  return 0;
}
