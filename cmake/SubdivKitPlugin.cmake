# subdivkit_add_plugin(<target> <source>... [INSTALL] [DESTINATION <dir>])
#
# Builds a SubdivKit plugin: a loadable module (<target>.so, no "lib" prefix) linked to
# SubdivKit::subdiv, compiled as C++20, with every symbol hidden except the entry point that
# SUBDIV_PLUGIN(...) exports.
#
#   INSTALL               install it into <prefix>/${CMAKE_INSTALL_LIBDIR}/subdivkit/plugins,
#                         the folder `subdiv` searches when SubdivKit is installed in the
#                         same prefix
#   DESTINATION <dir>     install it into <dir> instead (e.g. ${SubdivKit_PLUGIN_DIR}, the
#                         plugin folder of the SubdivKit that find_package found)
#
# Load it with `subdiv --plugin path/to/<target>.so ...`, through SUBDIV_PLUGIN_PATH, or by
# installing it into an installed plugin folder.
include_guard(GLOBAL)
include(GNUInstallDirs)

function(subdivkit_add_plugin target)
  cmake_parse_arguments(PARSE_ARGV 1 ARG "INSTALL" "DESTINATION" "")
  if(NOT ARG_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "subdivkit_add_plugin(${target}): give at least one source file")
  endif()
  if(NOT TARGET SubdivKit::subdiv)
    message(FATAL_ERROR "subdivkit_add_plugin(${target}): SubdivKit::subdiv is not defined; call find_package(SubdivKit) first")
  endif()
  add_library(${target} MODULE ${ARG_UNPARSED_ARGUMENTS})
  target_link_libraries(${target} PRIVATE SubdivKit::subdiv)
  target_compile_features(${target} PRIVATE cxx_std_20)
  set_target_properties(${target} PROPERTIES
    PREFIX ""
    CXX_EXTENSIONS OFF
    CXX_VISIBILITY_PRESET hidden
    VISIBILITY_INLINES_HIDDEN ON)
  if(ARG_DESTINATION)
    install(TARGETS ${target} LIBRARY DESTINATION "${ARG_DESTINATION}")
  elseif(ARG_INSTALL)
    install(TARGETS ${target} LIBRARY DESTINATION "${CMAKE_INSTALL_LIBDIR}/subdivkit/plugins")
  endif()
endfunction()
