# SPDX-License-Identifier: GPL-2.0-or-later
# tdem LIGGGHTS module 'grate' (included by src/pair_styles/liggghts/CMakeLists.txt)
set(TDEM_LIG_MODULE_SOURCES ${CMAKE_CURRENT_LIST_DIR}/grate_register.cpp)
set(TDEM_LIG_MODULE_INCLUDES ${CMAKE_CURRENT_LIST_DIR})
