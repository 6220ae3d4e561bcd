# SPDX-License-Identifier: GPL-2.0-or-later
# tdem LAMMPS module 'clump': sources of its styles (included by src/pair_styles/lammps/CMakeLists.txt)
list(APPEND TDEM_LAMMPS_STYLE_SOURCES
     ${CMAKE_CURRENT_LIST_DIR}/fix_tdem_clump.cpp
     ${CMAKE_CURRENT_LIST_DIR}/fix_tdem_correction.cpp
     ${CMAKE_CURRENT_LIST_DIR}/clump_styles.cpp)
list(APPEND TDEM_LAMMPS_MODULE_INCLUDES ${CMAKE_CURRENT_LIST_DIR})
