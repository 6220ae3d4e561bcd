# SPDX-License-Identifier: GPL-2.0-or-later
# fix tdem/grate for LIGGGHTS (module 'grate', src/fixes/grate/liggghts; docs/liggghts/fix_tdem_grate.md): included by
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
# the three grate scenes (forward 2D/3D, reverse 3D, standing grate) in their short version on 2
# ranks with the mixing analysis: runs, transports the bed, P' > 0, Q' of fix tdem/mixing/depth =
# Q' recomputed from the dumped D (validation/grate/analyse.py checks; exit 1 if one fails)
if(TDEM_LIGGGHTS_MIXING)
  add_test(NAME liggghts.grate.scenes_short_transport_and_mixing
           COMMAND sh ${PROJECT_SOURCE_DIR}/validation/grate/run.sh --short)
  set_tests_properties(liggghts.grate.scenes_short_transport_and_mixing PROPERTIES
                       LABELS liggghts TIMEOUT 600 PROCESSORS 2
                       ENVIRONMENT "TDEM_LIGGGHTS=$<TARGET_FILE:tdem-liggghts>;WORKDIR=${_work}/grate_scenes")
endif()
