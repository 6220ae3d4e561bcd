# SPDX-License-Identifier: GPL-2.0-or-later
# The LAMMPS host tests of one LAMMPS version (included once per version by CMakeLists.txt):
# test names ${_pfx}.<test>, label ${_lbl}, arguments ${_args} (--tdem, --lmp, --plugin, ...).

foreach(t equivalence granular_models restitution parallel_restart plugin examples bad_input hertz walton_braun
          thornton rolling restart_legacy)
  add_test(NAME ${_pfx}.${t}
           COMMAND ${TDEM_PYTHON3} ${CMAKE_CURRENT_SOURCE_DIR}/test_${t}.py ${_args})
  set_tests_properties(${_pfx}.${t} PROPERTIES LABELS ${_lbl} TIMEOUT 600)
endforeach()
# the energy accounting (issue 23): pair_style tdem/gran energy yes and compute tdem/energy against
# the closed forms and LAMMPS's kinetic energy; a settling bed on 1 and 2 ranks; restart
add_test(NAME ${_pfx}.energy COMMAND ${TDEM_PYTHON3} ${CMAKE_CURRENT_SOURCE_DIR}/test_energy.py ${_args})
set_tests_properties(${_pfx}.energy PROPERTIES LABELS ${_lbl} TIMEOUT 600 PROCESSORS 2)
# the style pages of docs/lammps/: sections in the manual's order, links, every example runs
add_test(NAME ${_pfx}.doc_examples
         COMMAND ${TDEM_PYTHON3} ${CMAKE_CURRENT_SOURCE_DIR}/../test_doc_examples.py ${_args} --engine lammps
                 --docs ${PROJECT_SOURCE_DIR}/docs)
set_tests_properties(${_pfx}.doc_examples PROPERTIES LABELS ${_lbl} TIMEOUT 600)
# host vs the single-collision harness tdem-collide (every normal law, wall and pair impacts)
if(TARGET tdem-collide)
  add_test(NAME ${_pfx}.harness_agreement
           COMMAND ${TDEM_PYTHON3} ${CMAKE_CURRENT_SOURCE_DIR}/test_harness_agreement.py ${_args}
                   --collide $<TARGET_FILE:tdem-collide>)
  set_tests_properties(${_pfx}.harness_agreement PROPERTIES LABELS ${_lbl} TIMEOUT 600)
  # the tangential laws: oblique impacts vs the harness, slope, rolling, restart, MPI
  add_test(NAME ${_pfx}.tangential
           COMMAND ${TDEM_PYTHON3} ${CMAKE_CURRENT_SOURCE_DIR}/test_tangential.py ${_args}
                   --collide $<TARGET_FILE:tdem-collide>)
  set_tests_properties(${_pfx}.tangential PROPERTIES LABELS ${_lbl} TIMEOUT 600 PROCESSORS 2)
  # fix tdem/integrate: a sphere-wall impact with every scheme vs tdem-collide --scheme
  add_test(NAME ${_pfx}.integrate_harness
           COMMAND ${TDEM_PYTHON3} ${CMAKE_CURRENT_SOURCE_DIR}/test_integrate.py ${_args}
                   --collide $<TARGET_FILE:tdem-collide> --part harness)
  set_tests_properties(${_pfx}.integrate_harness PROPERTIES LABELS ${_lbl} TIMEOUT 600)
  # grid_correction on (issue 22): impacts vs tdem-collide --grid-correction on
  add_test(NAME ${_pfx}.grid_correction_harness
           COMMAND ${TDEM_PYTHON3} ${CMAKE_CURRENT_SOURCE_DIR}/test_grid_correction.py ${_args}
                   --collide $<TARGET_FILE:tdem-collide> --part harness)
  set_tests_properties(${_pfx}.grid_correction_harness PROPERTIES LABELS ${_lbl} TIMEOUT 600)
endif()
# grid_correction on: columns at rest unchanged, MPI + restart, bad input
foreach(p unchanged mpi bad_input)
  add_test(NAME ${_pfx}.grid_correction_${p}
           COMMAND ${TDEM_PYTHON3} ${CMAKE_CURRENT_SOURCE_DIR}/test_grid_correction.py ${_args} --part ${p})
  set_tests_properties(${_pfx}.grid_correction_${p} PROPERTIES LABELS ${_lbl} TIMEOUT 600)
endforeach()
set_tests_properties(${_pfx}.grid_correction_mpi PROPERTIES PROCESSORS 2)
# fix tdem/integrate (src/integrators/lammps): velocity_verlet = nve/sphere and free flight,
# multi-step history through MPI and restart (two groups of schemes), bad input
add_test(NAME ${_pfx}.integrate_nve
         COMMAND ${TDEM_PYTHON3} ${CMAKE_CURRENT_SOURCE_DIR}/test_integrate.py ${_args} --part nve)
add_test(NAME ${_pfx}.integrate_restart_a
         COMMAND ${TDEM_PYTHON3} ${CMAKE_CURRENT_SOURCE_DIR}/test_integrate.py ${_args} --part restart
                 --schemes ab4,ab5,gear5,abm4)
add_test(NAME ${_pfx}.integrate_restart_b
         COMMAND ${TDEM_PYTHON3} ${CMAKE_CURRENT_SOURCE_DIR}/test_integrate.py ${_args} --part restart
                 --schemes beeman,gear6,taylor3,position_verlet,leapfrog)
add_test(NAME ${_pfx}.integrate_bad_input
         COMMAND ${TDEM_PYTHON3} ${CMAKE_CURRENT_SOURCE_DIR}/test_integrate.py ${_args} --part bad_input)
set_tests_properties(${_pfx}.integrate_nve ${_pfx}.integrate_restart_a ${_pfx}.integrate_restart_b
                     ${_pfx}.integrate_bad_input PROPERTIES LABELS ${_lbl} TIMEOUT 600)
set_tests_properties(${_pfx}.integrate_restart_a ${_pfx}.integrate_restart_b PROPERTIES PROCESSORS 2)
# the MPI test uses both cores
set_tests_properties(${_pfx}.parallel_restart ${_pfx}.walton_braun ${_pfx}.thornton PROPERTIES PROCESSORS 2)

# the plugin loaded with `plugin load` into this version's own lmp, where that has the PLUGIN
# package (shared-library build): equal to the stock styles there and to tdem-lammps
if(_stock_has_plugin)
  add_test(NAME ${_pfx}.plugin_host
           COMMAND ${TDEM_PYTHON3} ${CMAKE_CURRENT_SOURCE_DIR}/test_plugin_host.py ${_args}
                   --host ${_stock})
  set_tests_properties(${_pfx}.plugin_host PROPERTIES LABELS ${_lbl} TIMEOUT 600)
endif()

# tests of the optional modules and suites, each in its own file (tests_<name>.cmake) so that
# they can be added independently; a module's tests are skipped when the module is off
foreach(_m grate mixing timestep clump stability)
  if(EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/tests_${_m}.cmake)
    include(${CMAKE_CURRENT_SOURCE_DIR}/tests_${_m}.cmake)
  endif()
endforeach()
# the DEM verification suite (validation/dem_suite, issue 18): DEM-01 ... DEM-11 with tdem's laws
# against the closed forms, 1 and 2 ranks, the stock styles of equal physics in this version's lmp
if(_mode STREQUAL tdem)
  add_test(NAME ${_pfx}.dem_suite
           COMMAND ${TDEM_PYTHON3} ${PROJECT_SOURCE_DIR}/validation/dem_suite/dem_suite.py --host lammps
                   --exe ${_tdem} --stock ${_stock} --version ${_v} --mpirun ${TDEM_MPIRUN}
                   --workdir ${CMAKE_CURRENT_BINARY_DIR}/dem_suite_${_pfx})
  set_tests_properties(${_pfx}.dem_suite PROPERTIES LABELS "${_lbl};dem_suite" TIMEOUT 600)
endif()
# the generated bad-input sweep (issue 17): every argument of every law and fix, two cases at a
# time; the parsers are the same code in every version (their error paths are covered per version
# by bad_input), so it runs once, with the main LAMMPS
if(_mode STREQUAL tdem AND _main)
  add_test(NAME ${_pfx}.sweep COMMAND ${TDEM_PYTHON3} ${CMAKE_CURRENT_SOURCE_DIR}/test_sweep.py ${_args})
  set_tests_properties(${_pfx}.sweep PROPERTIES LABELS ${_lbl} TIMEOUT 900 PROCESSORS 2)
  # the same for fix tdem/clump, tdem/grate, tdem/mixing/* and tdem/integrate (tests/host/fix_sweep.py)
  if(TDEM_LAMMPS_GRATE AND TDEM_LAMMPS_MIXING AND TDEM_LAMMPS_CLUMP)
    add_test(NAME ${_pfx}.sweep_fixes COMMAND ${TDEM_PYTHON3} ${CMAKE_CURRENT_SOURCE_DIR}/test_sweep_fixes.py ${_args})
    set_tests_properties(${_pfx}.sweep_fixes PROPERTIES LABELS ${_lbl} TIMEOUT 900 PROCESSORS 2)
  endif()
endif()
