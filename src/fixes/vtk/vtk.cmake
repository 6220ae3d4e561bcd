# SPDX-License-Identifier: GPL-2.0-or-later
# tdem_vtk: VTK XML output of the fixes' own geometry (src/fixes/vtk/vtk_files.h) through the VTK
# library of Debian (libvtk9-dev, VTK 9.1, the VTK that Debian's LIGGGHTS links too). A static
# library, position independent, linked into tdem-liggghts, tdem-lammps and the LAMMPS plugins.
find_package(VTK 9.1 QUIET COMPONENTS CommonCore CommonDataModel IOXML)
if(NOT VTK_FOUND)
  message(FATAL_ERROR "tdem: VTK 9 (components CommonCore CommonDataModel IOXML) not found "
                      "(Debian: apt install libvtk9-dev; tools/setup.sh installs it)")
endif()
message(STATUS "tdem: VTK ${VTK_VERSION} for the VTK XML output")
add_library(tdem_vtk STATIC ${CMAKE_CURRENT_LIST_DIR}/vtk_files.cpp)
target_link_libraries(tdem_vtk PUBLIC tdem_core PRIVATE VTK::CommonCore VTK::CommonDataModel VTK::IOXML)
set_target_properties(tdem_vtk PROPERTIES POSITION_INDEPENDENT_CODE ON)
