# SPDX-License-Identifier: GPL-2.0-or-later
# fix tdem/clump for LIGGGHTS (module 'clump', src/fixes/clumps/liggghts; docs/liggghts/fix_tdem_clump.md): included by
# tests/host/liggghts/CMakeLists.txt. One-sphere clumps = nve/sphere, torque-free asymmetric body,
# flat-face impacts against the N-contact closed form, -np 2 = -np 1, -np 1/2/4/8 bitwise (ranks), restart,
# insertion, bad input;
# the multiple-contact correction (corr*: count/overlap flat impacts, continuity, local_mass, -np 2 and restart;
# corrstock: the stock hertz model scaled through surface tdem/clump; corrsurf: the keyword's errors and warning);
# stock_*: fix tdem/correction for the bodies of the stock fix multisphere (flat: count/overlap, local: local_mass).
if(NOT TDEM_LIGGGHTS_CLUMP)
  return()
endif()
foreach(_part nve torquefree flatface parallel restart insert bad examples periodic ranks
              corrflat corrcont corrlocal corrpar corrwide corrstock corrsurf vtk)
  add_test(NAME liggghts.clump.${_part}
           COMMAND ${TDEM_LIGGGHTS_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test_clump.py --part ${_part}
                   --tdem $<TARGET_FILE:tdem-liggghts> --stock ${TDEM_LIGGGHTS_STOCK}
                   --mpirun ${_mpirun} --workdir ${_work}
           WORKING_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR})
  set_tests_properties(liggghts.clump.${_part} PROPERTIES LABELS liggghts TIMEOUT 300
                       ENVIRONMENT PYTHONDONTWRITEBYTECODE=1)
endforeach()
# fix tdem/correction with the stock fix multisphere (test_clump_stock.py)
foreach(_part flat local bad)
  add_test(NAME liggghts.clump.stock_${_part}
           COMMAND ${TDEM_LIGGGHTS_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test_clump_stock.py --part ${_part}
                   --tdem $<TARGET_FILE:tdem-liggghts> --stock ${TDEM_LIGGGHTS_STOCK}
                   --mpirun ${_mpirun} --workdir ${_work}
           WORKING_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR})
  set_tests_properties(liggghts.clump.stock_${_part} PROPERTIES LABELS liggghts TIMEOUT 300
                       ENVIRONMENT PYTHONDONTWRITEBYTECODE=1)
endforeach()
set_tests_properties(liggghts.clump.stock_flat liggghts.clump.stock_local PROPERTIES PROCESSORS 2)
set_tests_properties(liggghts.clump.parallel liggghts.clump.insert liggghts.clump.examples
                     liggghts.clump.periodic liggghts.clump.corrpar liggghts.clump.corrwide liggghts.clump.ranks
                     liggghts.clump.vtk PROPERTIES PROCESSORS 2)
