# SPDX-License-Identifier: GPL-2.0-or-later
# tdem LIGGGHTS module 'grate' (included by src/pair_styles/liggghts/CMakeLists.txt):
# fix tdem/grate (docs/liggghts/fix_tdem_grate.md)
set(TDEM_LIG_MODULE_SOURCES ${CMAKE_CURRENT_LIST_DIR}/grate_register.cpp
                            ${CMAKE_CURRENT_LIST_DIR}/fix_tdem_grate.cpp)
set(TDEM_LIG_MODULE_INCLUDES ${CMAKE_CURRENT_LIST_DIR})
