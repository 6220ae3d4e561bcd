# SPDX-License-Identifier: GPL-2.0-or-later
# module 'mixing' (compute tdem/mixing/velocity, fix tdem/mixing/depth; docs/mixing_hosts.md)
if(TDEM_LAMMPS_MIXING)
  foreach(_p velocity depth rate mpi restart bad_input)
    add_test(NAME ${_pfx}.mixing.${_p}
             COMMAND ${TDEM_PYTHON3} ${CMAKE_CURRENT_SOURCE_DIR}/test_mixing.py ${_args} --part ${_p})
    set_tests_properties(${_pfx}.mixing.${_p} PROPERTIES LABELS ${_lbl} TIMEOUT 300)
  endforeach()
  set_tests_properties(${_pfx}.mixing.mpi ${_pfx}.mixing.restart PROPERTIES PROCESSORS 2)
endif()
