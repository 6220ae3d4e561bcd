# SPDX-License-Identifier: GPL-2.0-or-later
# module 'mixing' (compute tdem/mixing/velocity, fix tdem/mixing/depth; docs/mixing_hosts.md)
if(TDEM_LAMMPS_MIXING)
  foreach(_p velocity depth rate mpi restart bad_input)
    add_test(NAME lammps.mixing.${_p}
             COMMAND ${TDEM_PYTHON3} ${CMAKE_CURRENT_SOURCE_DIR}/test_mixing.py ${_args} --part ${_p})
    set_tests_properties(lammps.mixing.${_p} PROPERTIES LABELS lammps TIMEOUT 300)
  endforeach()
  set_tests_properties(lammps.mixing.mpi lammps.mixing.restart PROPERTIES PROCESSORS 2)
endif()
