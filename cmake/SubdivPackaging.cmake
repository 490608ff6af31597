# Debian packages from this build tree with CPack's DEB generator (scripts/package.sh;
# docs/install.md says why CPack rather than debian/ + dpkg-buildpackage). One package per
# install component:
#   lib      -> libsubdivkit          shared libraries, built-in schemes, example plugins
#   dev      -> libsubdivkit-dev      headers, .so links, CMake package (find_package(SubdivKit))
#   tools    -> subdivkit-tools       `subdiv` and its man page (help2man from --help)
#   python   -> python3-subdivkit     the subdivkit module, in /usr/lib/python3/dist-packages
#   paraview_plugin, paraview_autoload (the plugin, its module, its .plugins.xml, and the
#              paraview.conf that loads it at start) -> paraview-subdivkit,
#              when the ParaView plugin is built (SubdivKit's VTK is ParaView's)
# Depends come from dpkg-shlibdeps (Debian's names and versions of the libraries each
# package links) plus the packages of this build that each one needs.
# Included at the end of the top-level CMakeLists.txt, when every install rule is known.

# The man page, generated from `subdiv --help` and each command's (Debian's help2man).
find_program(SUBDIV_HELP2MAN help2man)
if(SUBDIV_HELP2MAN AND TARGET subdiv_cli AND NOT SUBDIV_SANITIZE)  # runs the built subdiv
  set(man_page ${PROJECT_BINARY_DIR}/man/subdiv.1.gz)
  add_custom_command(OUTPUT ${man_page}
    COMMAND ${CMAKE_COMMAND} -DSUBDIV=$<TARGET_FILE:subdiv_cli> -DHELP2MAN=${SUBDIV_HELP2MAN}
            -DVERSION=${PROJECT_VERSION} -DOUT=${PROJECT_BINARY_DIR}/man -P ${PROJECT_SOURCE_DIR}/cmake/SubdivManPage.cmake
    DEPENDS subdiv_cli ${PROJECT_SOURCE_DIR}/cmake/SubdivManPage.cmake COMMENT "subdiv.1 (help2man)")
  add_custom_target(subdiv_man_page ALL DEPENDS ${man_page})
  install(FILES ${man_page} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1 COMPONENT tools)
else()
  message(STATUS "subdiv man page: not generated (install help2man)")
endif()

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME subdivkit)
set(CPACK_PACKAGE_VENDOR "SubdivKit")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_CONTACT "SubdivKit maintainers <subdivkit@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "subdivision schemes as data: one engine refines any mesh")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_PACKAGE_DIRECTORY ${PROJECT_BINARY_DIR}/packages)
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # <name>_<version>-<release>_<arch>.deb
set(CPACK_DEBIAN_PACKAGE_RELEASE 1)  # subdiv_lib_depends below names it too
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# The packages of this build that each one needs, as explicit Depends (CPack's component
# dependencies do not carry over when the ParaView components are grouped into one package).
set(subdiv_lib_depends "libsubdivkit (= ${PROJECT_VERSION}-1)")
set(CPACK_DEBIAN_PACKAGE_GENERATE_SHLIBS ON)
# The packages' own libraries, for dpkg-shlibdeps while they are not installed yet.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS_PRIVATE_DIRS
    ${PROJECT_BINARY_DIR}/framework)

set(CPACK_DEBIAN_LIB_PACKAGE_NAME libsubdivkit)
set(CPACK_DEBIAN_LIB_PACKAGE_SECTION libs)
set(CPACK_COMPONENT_LIB_DESCRIPTION "SubdivKit: subdivision schemes as data, one engine for any mesh (shared libraries)
 libsubdiv refines any polygon mesh with a scheme given as a JSON file or a plugin;
 libsubdiv_vtkio reads and writes VTK files. Includes the built-in schemes (Catmull-Clark,
 Loop, Doo-Sabin, butterfly, sqrt3 and more) and the example plugins.")

set(CPACK_DEBIAN_DEV_PACKAGE_NAME libsubdivkit-dev)
set(CPACK_DEBIAN_DEV_PACKAGE_SECTION libdevel)
set(CPACK_DEBIAN_DEV_PACKAGE_DEPENDS "${subdiv_lib_depends}")
set(CPACK_COMPONENT_DEV_DESCRIPTION "SubdivKit: development files
 The public headers, the CMake package (find_package(SubdivKit): SubdivKit::subdiv,
 SubdivKit::vtkio, subdivkit_add_plugin) for programs and plugins.")

set(CPACK_DEBIAN_TOOLS_PACKAGE_NAME subdivkit-tools)
set(CPACK_DEBIAN_TOOLS_PACKAGE_DEPENDS "${subdiv_lib_depends}")
set(CPACK_COMPONENT_TOOLS_DESCRIPTION "SubdivKit: the subdiv command line
 subdiv refines meshes with subdivision schemes and writes files for ParaView, lists and
 validates schemes, analyses their convergence and smoothness, and interpolates points.")

set(CPACK_DEBIAN_PYTHON_PACKAGE_NAME python3-subdivkit)
set(CPACK_DEBIAN_PYTHON_PACKAGE_SECTION python)
if(Python3_VERSION)
  math(EXPR next_minor_number "${Python3_VERSION_MINOR} + 1")
  # The extension module is built for this Python's ABI: that Python, and NumPy.
  set(CPACK_DEBIAN_PYTHON_PACKAGE_DEPENDS "${subdiv_lib_depends}, python3 (>= ${Python3_VERSION_MAJOR}.${Python3_VERSION_MINOR}), python3 (<< ${Python3_VERSION_MAJOR}.${next_minor_number}), python3-numpy")
else()
  set(CPACK_DEBIAN_PYTHON_PACKAGE_DEPENDS "${subdiv_lib_depends}, python3-numpy")
endif()
set(CPACK_DEBIAN_PYTHON_PACKAGE_SUGGESTS "python3-scipy")
set(CPACK_DEBIAN_PYTHON_PACKAGE_CONTROL_EXTRA ${PROJECT_SOURCE_DIR}/cmake/debian/python3-subdivkit/prerm)
set(CPACK_COMPONENT_PYTHON_DESCRIPTION "SubdivKit: Python 3 module
 subdivkit refines, analyses and evaluates subdivision schemes over NumPy arrays.")

# The ParaView plugin (plugins/paraview): its library and module, its .plugins.xml and the
# paraview.conf that loads it at start, one package.
get_cmake_property(all_components COMPONENTS)
set(subdiv_own_components lib dev tools python)
set(paraview_components "")
foreach(component IN ITEMS paraview_plugin paraview_autoload)
  if(component IN_LIST all_components)
    list(APPEND paraview_components ${component})
  endif()
endforeach()
set(CPACK_COMPONENTS_ALL ${subdiv_own_components})
if(TARGET SubdivKit AND paraview_components)
  foreach(component IN LISTS paraview_components)
    string(TOUPPER ${component} upper)
    set(CPACK_COMPONENT_${upper}_GROUP paraview)
  endforeach()
  foreach(component IN LISTS subdiv_own_components)  # one group each, described as before
    string(TOUPPER ${component} upper)
    set(CPACK_COMPONENT_${upper}_GROUP ${component})
    set(CPACK_COMPONENT_GROUP_${upper}_DESCRIPTION "${CPACK_COMPONENT_${upper}_DESCRIPTION}")
  endforeach()
  set(CPACK_COMPONENTS_GROUPING ONE_PER_GROUP)
  list(APPEND CPACK_COMPONENTS_ALL ${paraview_components})
  set(CPACK_DEBIAN_PARAVIEW_PACKAGE_NAME paraview-subdivkit)
  set(CPACK_DEBIAN_PARAVIEW_PACKAGE_DEPENDS "${subdiv_lib_depends}, paraview")
  set(CPACK_COMPONENT_GROUP_PARAVIEW_DESCRIPTION "SubdivKit: ParaView plugin
 The filters SubdivKit Refine and SubdivKit Analyze, loaded when ParaView starts.")
endif()
list(REMOVE_ITEM all_components ${CPACK_COMPONENTS_ALL})
if(all_components)
  message(STATUS "Debian packages: install components left out: ${all_components}")
endif()
include(CPack)
