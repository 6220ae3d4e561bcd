// SPDX-License-Identifier: GPL-2.0-or-later
// tdem-liggghts: a drop-in for the `liggghts` executable (same command line: -in, -var, -log,
// -echo, -screen, ...) with the tdem contact laws registered before the LAMMPS instance is
// created. Everything else is what LIGGGHTS's own main program does.
#include <mpi.h>

#include <csignal>
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

  LAMMPS_NS::LAMMPS* lammps = new LAMMPS_NS::LAMMPS(argc, argv, MPI_COMM_WORLD);
  tdem::liggghts::attach(lammps);
  lammps->input->file();
  tdem::liggghts::attach(nullptr);
  delete lammps;

  MPI_Finalize();
  return 0;
}
