# SPDX-License-Identifier: GPL-2.0-or-later
# fix tdem/clump (module clump, src/fixes/clumps/lammps): included by tests/host/lammps/CMakeLists.txt
if(NOT TDEM_LAMMPS_CLUMP)
  return()
endif()
foreach(_p nve_single free_body flat_impact mpi restart insert bad_input
          corr_flat corr_continuity corr_local_mass corr_mpi ranks corr_stock corr_stock_local corr_wide vtk)
  add_test(NAME ${_pfx}.clump.${_p}
           COMMAND ${TDEM_PYTHON3} ${CMAKE_CURRENT_SOURCE_DIR}/test_clump.py ${_args} --part ${_p})
  set_tests_properties(${_pfx}.clump.${_p} PROPERTIES LABELS ${_lbl} TIMEOUT 600)
endforeach()
set_tests_properties(${_pfx}.clump.mpi ${_pfx}.clump.restart ${_pfx}.clump.insert ${_pfx}.clump.corr_mpi ${_pfx}.clump.ranks
                     ${_pfx}.clump.corr_stock ${_pfx}.clump.corr_stock_local ${_pfx}.clump.corr_wide ${_pfx}.clump.vtk
                     PROPERTIES PROCESSORS 2)
