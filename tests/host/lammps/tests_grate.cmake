# SPDX-License-Identifier: GPL-2.0-or-later
# fix tdem/grate (module 'grate', src/fixes/grate/lammps): bar kinematics vs an independent model (VTK and
# the group motion), carrying by moving bars (3D, reverse grate, 2D disks), impacts vs the closed
# forms (face, joint of two rows, bar edge), -np 2 = -np 1 and restart with two-box contacts, bad input.
if(NOT TDEM_LAMMPS_GRATE)
  return()
endif()
foreach(_part kinematics carry impact parallel bad_input twod scene)
  add_test(NAME ${_pfx}.grate.${_part}
           COMMAND ${TDEM_PYTHON3} ${CMAKE_CURRENT_SOURCE_DIR}/test_grate.py ${_args} --part ${_part})
  set_tests_properties(${_pfx}.grate.${_part} PROPERTIES LABELS ${_lbl} TIMEOUT 300)
endforeach()
set_tests_properties(${_pfx}.grate.parallel ${_pfx}.grate.scene PROPERTIES PROCESSORS 2)
