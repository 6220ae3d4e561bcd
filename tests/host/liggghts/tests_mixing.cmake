# SPDX-License-Identifier: GPL-2.0-or-later
# module 'mixing' (compute tdem/mixing/velocity, fix tdem/mixing/depth; docs/mixing_hosts.md)
if(TDEM_LIGGGHTS_MIXING AND TARGET tdem-liggghts)
  foreach(_p velocity depth rate parallel bad_input)
    add_test(NAME liggghts.mixing.${_p}
             COMMAND ${TDEM_LIGGGHTS_PYTHON} ${CMAKE_CURRENT_SOURCE_DIR}/test_mixing.py
                     --tdem $<TARGET_FILE:tdem-liggghts> --stock ${TDEM_LIGGGHTS_STOCK}
                     --mpirun ${_mpirun} --workdir ${_work} --part ${_p}
             WORKING_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR})
    set_tests_properties(liggghts.mixing.${_p} PROPERTIES LABELS liggghts TIMEOUT 300
                         ENVIRONMENT PYTHONDONTWRITEBYTECODE=1)
  endforeach()
  set_tests_properties(liggghts.mixing.parallel PROPERTIES PROCESSORS 2)
endif()
