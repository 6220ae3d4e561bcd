# SPDX-License-Identifier: GPL-2.0-or-later
# tdem LIGGGHTS module 'clump' (included by src/pair_styles/liggghts/CMakeLists.txt):
# fix tdem/clump, fix tdem/correction (docs/liggghts/fix_tdem_clump.md)
set(TDEM_LIG_MODULE_SOURCES ${CMAKE_CURRENT_LIST_DIR}/clump_register.cpp
                            ${CMAKE_CURRENT_LIST_DIR}/fix_tdem_clump.cpp
                            ${CMAKE_CURRENT_LIST_DIR}/clump_correction.cpp
                            ${CMAKE_CURRENT_LIST_DIR}/fix_tdem_correction.cpp)
set(TDEM_LIG_MODULE_INCLUDES ${CMAKE_CURRENT_LIST_DIR})
