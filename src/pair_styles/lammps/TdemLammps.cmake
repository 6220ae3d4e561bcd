# SPDX-License-Identifier: GPL-2.0-or-later
# tdem_lammps_build(<suffix> <header_dir> <library> <stock_lmp> <main>)
#
# The LAMMPS half of tdem for one LAMMPS version, from the same sources for every version:
#   <header_dir>  the src/ directory of that LAMMPS's source tree (its full set of headers)
#   <library>     its liblammps.so for tdem-lammps, or "" (then only the plugin is built)
#   <stock_lmp>   that version's own lmp (the reference of the host tests), or ""
#   <main>        ON for the LAMMPS the build is for (the Debian package, or the user's),
#                 OFF for the extra test versions (TDEM_LAMMPS_EXTRA)
# Targets, with <suffix> "" for the main version and "_<name>" (e.g. _4Jul2026) otherwise:
#   tdem_lammps_headers<suffix>   usage requirements (headers, API feature macros)
#   tdem_lammps_styles<suffix>    the style objects (position independent: for tdem-lammps and
#                                 the plugin alike)
#   tdem-lammps[-<name>]          bin/: drop-in for lmp linked against <library>
#   tdem_lammps_plugin<suffix>    lib/[lammps-<name>/]tdem_lammps_plugin.so
# The version is recorded in the global properties TDEM_LAMMPS_VERSIONS (names) and
# TDEM_LAMMPS_<name>_{MAIN,EXE,PLUGIN,STOCK,HEADERS} for the tests.
include(${CMAKE_CURRENT_LIST_DIR}/LammpsFeatures.cmake)

function(tdem_lammps_build suffix header_dir library stock_lmp main)
  file(STRINGS "${header_dir}/version.h" _ver REGEX "define LAMMPS_VERSION ")
  string(REGEX REPLACE ".*\"(.*)\".*" "\\1" _ver "${_ver}")
  string(REPLACE " " "" _name "${_ver}")  # "4 Jul 2026" -> 4Jul2026
  tdem_lammps_features(_defs "${header_dir}" "${_name}")
  set(_featdir ${CMAKE_BINARY_DIR}/lammps-features/${_name})
  tdem_lammps_write_features(${_featdir}/tdem_lammps_features.h ${_defs})

  set(_hdr tdem_lammps_headers${suffix})
  add_library(${_hdr} INTERFACE)
  target_include_directories(${_hdr} BEFORE INTERFACE ${header_dir} ${TDEM_LAMMPS_ADAPTER_INCLUDES} ${_featdir})
  target_compile_definitions(${_hdr} INTERFACE LAMMPS_SMALLBIG ${TDEM_LAMMPS_MODULE_DEFS})
  target_compile_options(${_hdr} INTERFACE -Wno-unused-parameter -Wno-cast-function-type)
  # Straight-line (SLP) vectorisation packs the x/y/z arithmetic of the contact loop into SSE2
  # pairs and adds shuffles and spills: measured with callgrind on bench/in.chute, the pair
  # loop needs 17 % more instructions than the stock gran/hooke/history with it, 2 % without.
  # (SLP does not reassociate, so results are bitwise the same either way.)
  target_compile_options(${_hdr} INTERFACE $<$<CXX_COMPILER_ID:GNU>:-fno-tree-slp-vectorize>
                                           $<$<CXX_COMPILER_ID:Clang>:-fno-slp-vectorize>)
  target_link_libraries(${_hdr} INTERFACE tdem_core tdem_vtk MPI::MPI_CXX)

  set(_drv ${PROJECT_SOURCE_DIR}/src/drivers/lammps)
  if(main)
    set(_exe tdem-lammps)
    set(_libdir ${CMAKE_BINARY_DIR}/lib)
  else()
    set(_exe tdem-lammps-${_name})
    set(_libdir ${CMAKE_BINARY_DIR}/lib/lammps-${_name})
  endif()

  add_library(tdem_lammps_styles${suffix} OBJECT ${TDEM_LAMMPS_STYLE_SOURCES})
  target_link_libraries(tdem_lammps_styles${suffix} PUBLIC ${_hdr})
  if(library)
    add_executable(${_exe} ${_drv}/main.cpp $<TARGET_OBJECTS:tdem_lammps_styles${suffix}>)
    target_link_libraries(${_exe} PRIVATE ${_hdr} ${library} MPI::MPI_CXX ${CMAKE_DL_LIBS})
    # export only the LAMMPS::post_create interposer (re-registration after `clear`)
    target_link_options(${_exe} PRIVATE "LINKER:--dynamic-list=${_drv}/tdem-lammps.dynlist")
    get_filename_component(_libpath "${library}" DIRECTORY)
    set_target_properties(${_exe} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/bin
                          LINK_DEPENDS ${_drv}/tdem-lammps.dynlist BUILD_RPATH "${_libpath}")
  endif()

  # The plugin: the same style objects in a module. It is not linked against
  # liblammps: the host process (tdem-lammps or a PLUGIN-enabled lmp) provides those symbols.
  # -Bsymbolic binds the plugin's own symbols internally, so a host that also contains the tdem
  # styles never mixes the two copies. The file name ends in "plugin.so", so LAMMPS_PLUGIN_PATH
  # auto-loading picks it up.
  add_library(tdem_lammps_plugin${suffix} MODULE ${_drv}/tdem_lammps_plugin.cpp
              $<TARGET_OBJECTS:tdem_lammps_styles${suffix}>)
  target_link_libraries(tdem_lammps_plugin${suffix} PRIVATE ${_hdr})
  target_link_options(tdem_lammps_plugin${suffix} PRIVATE "LINKER:-Bsymbolic")
  set_target_properties(tdem_lammps_plugin${suffix} PROPERTIES PREFIX "" OUTPUT_NAME tdem_lammps_plugin
                        LIBRARY_OUTPUT_DIRECTORY ${_libdir})

  set_property(GLOBAL APPEND PROPERTY TDEM_LAMMPS_VERSIONS ${_name})
  set_property(GLOBAL PROPERTY TDEM_LAMMPS_${_name}_MAIN ${main})
  set_property(GLOBAL PROPERTY TDEM_LAMMPS_${_name}_SUFFIX "${suffix}")
  if(library)
    set_property(GLOBAL PROPERTY TDEM_LAMMPS_${_name}_EXE ${_exe})
  else()
    set_property(GLOBAL PROPERTY TDEM_LAMMPS_${_name}_EXE "")
  endif()
  set_property(GLOBAL PROPERTY TDEM_LAMMPS_${_name}_PLUGIN tdem_lammps_plugin${suffix})
  set_property(GLOBAL PROPERTY TDEM_LAMMPS_${_name}_STOCK "${stock_lmp}")
  set_property(GLOBAL PROPERTY TDEM_LAMMPS_${_name}_HEADERS "${header_dir}")
  if(library)
    set(_what "${_exe}, plugin")
  else()
    set(_what "plugin only (no liblammps given)")
  endif()
  message(STATUS "tdem LAMMPS ${_ver}: ${_what}; headers ${header_dir}; library ${library}")
endfunction()
