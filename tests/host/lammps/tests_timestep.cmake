# SPDX-License-Identifier: GPL-2.0-or-later
# module 'timestep': fix tdem/timestep (src/fixes/timestep/lammps), test_timestep_advice.py --part NAME
if(TDEM_LAMMPS_TIMESTEP)
  foreach(_p acceptance:unstable_at_1_1_dt_c_stable_at_0_5 closed_forms:printed_advice_matches_closed_forms
             check_modes:check_warn_stop_off runtime:runtime_check_on_raised_velocity bad_input:bad_input
             overdamped:overdamped_critical_step_closed_form)
    string(REPLACE ":" ";" _pp "${_p}")
    list(GET _pp 0 _part)
    list(GET _pp 1 _what)
    add_test(NAME ${_pfx}.timestep.${_what}
             COMMAND ${TDEM_PYTHON3} ${CMAKE_CURRENT_SOURCE_DIR}/test_timestep_advice.py ${_args} --part ${_part})
    set_tests_properties(${_pfx}.timestep.${_what} PROPERTIES LABELS ${_lbl} TIMEOUT 300)
  endforeach()
  # the run-time check also runs on 2 ranks
  set_tests_properties(${_pfx}.timestep.runtime_check_on_raised_velocity PROPERTIES PROCESSORS 2)
endif()
