# SPDX-License-Identifier: GPL-2.0-or-later
# tdem LIGGGHTS module 'mixing' (included by src/pair_styles/liggghts/CMakeLists.txt); the fix and the
# compute are shared with LAMMPS (../hosts/), the engine's names in src/fixes/liggghts/
set(TDEM_LIG_MODULE_SOURCES ${CMAKE_CURRENT_LIST_DIR}/mixing_register.cpp
    ${CMAKE_CURRENT_LIST_DIR}/../hosts/compute_tdem_mixing_velocity.cpp
    ${CMAKE_CURRENT_LIST_DIR}/../hosts/fix_tdem_mixing_depth.cpp)
set(TDEM_LIG_MODULE_INCLUDES ${CMAKE_CURRENT_LIST_DIR} ${CMAKE_CURRENT_LIST_DIR}/../hosts
    ${CMAKE_CURRENT_LIST_DIR}/../../liggghts ${CMAKE_CURRENT_LIST_DIR}/../../..)
