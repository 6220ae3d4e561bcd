# SPDX-License-Identifier: GPL-2.0-or-later
# module 'timestep': fix tdem/timestep (src/fixes/timestep/liggghts), test_timestep_advice.py --part NAME
if(TDEM_LIGGGHTS_TIMESTEP AND TARGET tdem-liggghts)
  foreach(_p acceptance:unstable_at_1_1_dt_c_stable_at_0_5 closed_forms:printed_advice_matches_closed_forms
             check_modes:check_warn_stop_off runtime:runtime_check_on_raised_velocity bad_input:bad_input
             tdem_laws:six_published_laws_match_closed_forms lsd_settings:model_setting_in_use_is_advised
             overdamped:overdamped_critical_step_closed_form)
    string(REPLACE ":" ";" _pp "${_p}")
    list(GET _pp 0 _part)
    list(GET _pp 1 _what)
    add_test(NAME liggghts.timestep.${_what}
             COMMAND ${TDEM_LIGGGHTS_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test_timestep_advice.py --part ${_part}
                     --tdem $<TARGET_FILE:tdem-liggghts> --stock ${TDEM_LIGGGHTS_STOCK}
                     --mpirun ${_mpirun} --workdir ${_work}
             WORKING_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR})
    set_tests_properties(liggghts.timestep.${_what} PROPERTIES LABELS liggghts TIMEOUT 300
                         ENVIRONMENT PYTHONDONTWRITEBYTECODE=1)
  endforeach()
  # the run-time check also runs on 2 ranks
  set_tests_properties(liggghts.timestep.runtime_check_on_raised_velocity PROPERTIES PROCESSORS 2)
endif()
