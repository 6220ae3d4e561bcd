# SPDX-License-Identifier: GPL-2.0-or-later
# fix tdem/grate for LIGGGHTS (module 'grate', src/grate/liggghts; docs/grate_liggghts.md): included by
# tests/host/liggghts/CMakeLists.txt. Bar kinematics vs an independent model (fix vector, VTK corners,
# the LIGGGHTS meshes' nodes and velocities), carrying by a moving bar (3D with and without rotation,
# 2D disks), rebound with the law's e (tdem/lsd and stock hooke, identical to a primitive plane),
# -np 2 = -np 1 and restart, bad input.
if(NOT TDEM_LIGGGHTS_GRATE)
  return()
endif()
foreach(_part kinematics carried rebound parallel bad 2d)
  add_test(NAME liggghts.grate.${_part}
           COMMAND ${TDEM_LIGGGHTS_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test_grate.py --part ${_part}
                   --tdem $<TARGET_FILE:tdem-liggghts> --stock ${TDEM_LIGGGHTS_STOCK}
                   --mpirun ${_mpirun} --workdir ${_work}
           WORKING_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR})
  set_tests_properties(liggghts.grate.${_part} PROPERTIES LABELS liggghts TIMEOUT 300
                       ENVIRONMENT PYTHONDONTWRITEBYTECODE=1)
endforeach()
set_tests_properties(liggghts.grate.parallel PROPERTIES PROCESSORS 2)
