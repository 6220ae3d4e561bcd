# SPDX-License-Identifier: GPL-2.0-or-later
# Stability suite (issue 8): one ctest per hard case, named after what it proves
# (test_stability.py --case NAME; closed forms in tests/host/stability_ref.py).
# The clump cases need the module `clump` (TDEM_LIGGGHTS_CLUMP), the grate cases `grate` (and `mixing`).
set(_stab_cases
    dt_0p9_critical_linear_stable_0p5_no_energy_gain
    stiff_200gpa_hertz_impacts_0p001_and_100_mps_bounded
    soft_1mpa_hertz_impacts_0p001_and_1_mps_bounded
    grazing_89deg_tangential_no_energy_gain_coulomb_bound
    mass_ratio_1_1000_head_on_momentum_and_e
    dense_bed_at_rest_1e5_steps_no_creep
    walton_braun_repeated_loading_no_gain_no_attraction
    thornton_repeated_loading_no_gain_no_attraction
    power_law_repeated_loading_no_gain_no_attraction
    extended_laws_v0_1e-4_and_v_max_e_in_0_1
    rank_crossing_in_contact_np2_equals_np1)
if(TDEM_LIGGGHTS_CLUMP)
  list(APPEND _stab_cases clump_8_simultaneous_contacts_no_energy_gain clump_pile_at_rest_no_creep)
endif()
if(TDEM_LIGGGHTS_GRATE)
  list(APPEND _stab_cases grate_moving_bars_energy_bounded)
  if(TDEM_LIGGGHTS_MIXING)
    list(APPEND _stab_cases grate_stopped_bed_at_rest_pprime_zero)
  endif()
endif()
foreach(_c ${_stab_cases})
  add_test(NAME liggghts.stability.${_c}
           COMMAND ${TDEM_LIGGGHTS_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test_stability.py --case ${_c}
                   --tdem $<TARGET_FILE:tdem-liggghts> --stock ${TDEM_LIGGGHTS_STOCK}
                   --mpirun ${_mpirun} --workdir ${_work}
           WORKING_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR})
  set_tests_properties(liggghts.stability.${_c} PROPERTIES LABELS "liggghts;stability" TIMEOUT 300
                       ENVIRONMENT PYTHONDONTWRITEBYTECODE=1)
endforeach()
set_tests_properties(liggghts.stability.rank_crossing_in_contact_np2_equals_np1 PROPERTIES PROCESSORS 2)
# the suite again with grid_correction on in every tdem normal law (issue 22): the cases without
# clumps and grates (whose models the correction does not reach)
foreach(_c dt_0p9_critical_linear_stable_0p5_no_energy_gain stiff_200gpa_hertz_impacts_0p001_and_100_mps_bounded
           soft_1mpa_hertz_impacts_0p001_and_1_mps_bounded grazing_89deg_tangential_no_energy_gain_coulomb_bound
           mass_ratio_1_1000_head_on_momentum_and_e dense_bed_at_rest_1e5_steps_no_creep
           walton_braun_repeated_loading_no_gain_no_attraction thornton_repeated_loading_no_gain_no_attraction
           power_law_repeated_loading_no_gain_no_attraction extended_laws_v0_1e-4_and_v_max_e_in_0_1
           rank_crossing_in_contact_np2_equals_np1)
  add_test(NAME liggghts.stability_gc.${_c}
           COMMAND ${TDEM_LIGGGHTS_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test_stability.py --case ${_c}
                   --tdem $<TARGET_FILE:tdem-liggghts> --stock ${TDEM_LIGGGHTS_STOCK}
                   --mpirun ${_mpirun} --workdir ${_work} --grid-correction on
           WORKING_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR})
  set_tests_properties(liggghts.stability_gc.${_c} PROPERTIES LABELS "liggghts;stability" TIMEOUT 300
                       ENVIRONMENT PYTHONDONTWRITEBYTECODE=1)
endforeach()
set_tests_properties(liggghts.stability_gc.rank_crossing_in_contact_np2_equals_np1 PROPERTIES PROCESSORS 2)
