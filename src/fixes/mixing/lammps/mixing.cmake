# SPDX-License-Identifier: GPL-2.0-or-later
# tdem LAMMPS module 'mixing': sources of its styles (included by src/pair_styles/lammps/CMakeLists.txt);
# the fix and the compute are shared with LIGGGHTS (../hosts/), the engine's names in src/fixes/lammps/
list(APPEND TDEM_LAMMPS_STYLE_SOURCES
     ${CMAKE_CURRENT_LIST_DIR}/mixing_styles.cpp
     ${CMAKE_CURRENT_LIST_DIR}/../hosts/compute_tdem_mixing_velocity.cpp
     ${CMAKE_CURRENT_LIST_DIR}/../hosts/fix_tdem_mixing_depth.cpp)
list(APPEND TDEM_LAMMPS_MODULE_INCLUDES ${CMAKE_CURRENT_LIST_DIR} ${CMAKE_CURRENT_LIST_DIR}/../hosts
     ${CMAKE_CURRENT_LIST_DIR}/../../lammps ${CMAKE_CURRENT_LIST_DIR}/../../..)
