# Which VTK SubdivKit's VTK file IO (subdiv_vtkio) and the tests build against. Debian 12
# has two, and a machine can hold only one of them with its Python: Debian's VTK
# (libvtk9-dev, whose python3-vtk9 conflicts with ParaView's Python) or the VTK inside
# ParaView's development files (paraview-dev, beside python3-paraview). Nothing else links
# VTK: libsubdiv is VTK-free.
#
# SUBDIV_VTK_PROVIDER: auto (Debian's if installed, else ParaView's), debian, or paraview.
# Sets SUBDIV_HAVE_VTK, SUBDIV_VTK_PROVIDER_FOUND ("debian" or "paraview") and
# SUBDIV_VTK_LIBRARIES (the VTK targets to link).
set(SUBDIV_VTK_PROVIDER auto CACHE STRING "VTK to build the VTK file IO against: auto, debian or paraview")
set_property(CACHE SUBDIV_VTK_PROVIDER PROPERTY STRINGS auto debian paraview)
set(subdiv_vtk_components CommonCore CommonDataModel IOXML IOLegacy)
set(subdiv_vtk_test_components IOGeometry IOPLY)  # optional: tests/ reads OBJ, PLY, STL back with VTK
unset(SUBDIV_VTK_PROVIDER_FOUND CACHE)  # decided afresh at every configure

if(SUBDIV_VTK_PROVIDER STREQUAL "auto" OR SUBDIV_VTK_PROVIDER STREQUAL "debian")
  # Debian's VTK installs its package config under cmake/vtk-9.1; ParaView's VTK is not on
  # the default search path (it lives under cmake/paraview-5.11/vtk), so this finds only
  # Debian's.
  find_package(VTK 9 QUIET COMPONENTS ${subdiv_vtk_components} OPTIONAL_COMPONENTS ${subdiv_vtk_test_components})
  # A build dir configured before with ParaView's VTK keeps that VTK_DIR in its cache, and
  # the search above then finds it again: the folder says whose VTK it is.
  if(VTK_FOUND AND VTK_DIR MATCHES "/paraview-[0-9.]+/vtk/?$")
    set(SUBDIV_VTK_PROVIDER_FOUND paraview)
  elseif(VTK_FOUND)
    set(SUBDIV_VTK_PROVIDER_FOUND debian)
  endif()
endif()
if(NOT SUBDIV_VTK_PROVIDER_FOUND AND (SUBDIV_VTK_PROVIDER STREQUAL "auto" OR SUBDIV_VTK_PROVIDER STREQUAL "paraview"))
  # ParaView ships its VTK's package config in cmake/paraview-<version>/vtk. Asking that
  # config for our four modules (rather than find_package(ParaView), which looks for the
  # dependencies of every ParaView module: Qt, MPI, HDF5, ...) needs only their few
  # dependencies' -dev packages (scripts/install-deps.sh installs them).
  file(GLOB subdiv_paraview_vtk_dirs
    ${ParaView_DIR}/vtk
    /usr/lib/${CMAKE_LIBRARY_ARCHITECTURE}/cmake/paraview-*/vtk
    /usr/local/lib/cmake/paraview-*/vtk /usr/local/lib/${CMAKE_LIBRARY_ARCHITECTURE}/cmake/paraview-*/vtk)
  if(subdiv_paraview_vtk_dirs)
    list(SORT subdiv_paraview_vtk_dirs COMPARE NATURAL ORDER DESCENDING)  # the newest ParaView
    list(GET subdiv_paraview_vtk_dirs 0 subdiv_paraview_vtk_dir)
    find_package(VTK CONFIG QUIET PATHS ${subdiv_paraview_vtk_dir} NO_DEFAULT_PATH
      COMPONENTS ${subdiv_vtk_components} OPTIONAL_COMPONENTS ${subdiv_vtk_test_components})
    if(VTK_FOUND)
      set(SUBDIV_VTK_PROVIDER_FOUND paraview)
    endif()
  endif()
endif()

if(SUBDIV_VTK_PROVIDER_FOUND)
  set(SUBDIV_VTK_PROVIDER_FOUND ${SUBDIV_VTK_PROVIDER_FOUND} CACHE INTERNAL "the VTK the build uses")
  set(SUBDIV_HAVE_VTK TRUE)
  set(SUBDIV_VTK_LIBRARIES VTK::CommonCore VTK::CommonDataModel VTK::IOXML VTK::IOLegacy)
  message(STATUS "VTK file IO against ${SUBDIV_VTK_PROVIDER_FOUND}'s VTK ${VTK_VERSION} (${VTK_DIR})")
else()
  message(FATAL_ERROR
    "No VTK found (SUBDIV_VTK_PROVIDER=${SUBDIV_VTK_PROVIDER}). Install one of them: "
    "`apt-get install libvtk9-dev` (Debian's VTK), or, where ParaView's Python (python3-paraview) is "
    "installed, `apt-get install paraview-dev` (ParaView's VTK). scripts/install-deps.sh picks the right one.")
endif()
