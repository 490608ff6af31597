# OpenSubdiv is the reference for tests and benchmarks. Debian's OpenSubdivConfig.cmake
# names static libraries the package does not ship, so find the shared library directly
# and expose it as the imported target OpenSubdiv::osdCPU (sets OpenSubdiv_FOUND).
find_path(OPENSUBDIV_INCLUDE_DIR opensubdiv/far/topologyRefiner.h)
find_library(OPENSUBDIV_CPU_LIBRARY NAMES osdCPU)
if(OPENSUBDIV_INCLUDE_DIR AND OPENSUBDIV_CPU_LIBRARY)
  set(OpenSubdiv_FOUND TRUE)
  if(NOT TARGET OpenSubdiv::osdCPU)
    add_library(OpenSubdiv::osdCPU SHARED IMPORTED)
    set_target_properties(OpenSubdiv::osdCPU PROPERTIES
      IMPORTED_LOCATION ${OPENSUBDIV_CPU_LIBRARY}
      INTERFACE_INCLUDE_DIRECTORIES ${OPENSUBDIV_INCLUDE_DIR})
  endif()
  message(STATUS "OpenSubdiv reference: ${OPENSUBDIV_CPU_LIBRARY}")
else()
  set(OpenSubdiv_FOUND FALSE)
  message(STATUS "OpenSubdiv not found: reference tests and benchmark comparisons are skipped")
endif()
