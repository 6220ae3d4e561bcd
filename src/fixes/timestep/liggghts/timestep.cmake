# SPDX-License-Identifier: GPL-2.0-or-later
# tdem LIGGGHTS module 'timestep': fix tdem/timestep (included by src/pair_styles/liggghts/CMakeLists.txt)
set(TDEM_LIG_MODULE_SOURCES ${CMAKE_CURRENT_LIST_DIR}/timestep_register.cpp
                            ${CMAKE_CURRENT_LIST_DIR}/fix_tdem_timestep.cpp)
set(TDEM_LIG_MODULE_INCLUDES ${CMAKE_CURRENT_LIST_DIR})
