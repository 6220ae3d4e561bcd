# SPDX-License-Identifier: GPL-2.0-or-later
# tdem LAMMPS module 'timestep': fix tdem/timestep (included by src/pair_styles/lammps/CMakeLists.txt)
list(APPEND TDEM_LAMMPS_STYLE_SOURCES
     ${CMAKE_CURRENT_LIST_DIR}/fix_tdem_timestep.cpp
     ${CMAKE_CURRENT_LIST_DIR}/timestep_styles.cpp)
list(APPEND TDEM_LAMMPS_MODULE_INCLUDES ${CMAKE_CURRENT_LIST_DIR})
