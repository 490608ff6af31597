# Refinement in pieces (docs/scale.md). Both libraries are optional:
#  - METIS (Debian's libmetis-dev) partitions the base mesh's faces; without it the engine
#    cuts them along a Morton curve. Sets the target subdiv_metis when found.
#  - MPI (Debian's libopenmpi-dev) lets `subdiv refine --pieces` spread the pieces over the
#    ranks of mpirun; without it the pieces are refined one after another in one process.
#    Only the subdiv tool links MPI, never libsubdiv. Sets SUBDIV_HAVE_MPI.
option(SUBDIV_WITH_METIS "Partition pieces with METIS when it is found" ON)
if(SUBDIV_WITH_METIS)
  find_path(METIS_INCLUDE_DIR metis.h)
  find_library(METIS_LIBRARY metis)
endif()
if(SUBDIV_WITH_METIS AND METIS_INCLUDE_DIR AND METIS_LIBRARY)
  add_library(subdiv_metis INTERFACE IMPORTED)
  target_include_directories(subdiv_metis INTERFACE ${METIS_INCLUDE_DIR})
  target_link_libraries(subdiv_metis INTERFACE ${METIS_LIBRARY})
  target_compile_definitions(subdiv_metis INTERFACE SUBDIV_HAVE_METIS=1)
  message(STATUS "METIS: ${METIS_LIBRARY} (pieces by graph partition)")
else()
  message(STATUS "METIS not found: pieces are cut along a Morton curve (install libmetis-dev for METIS)")
endif()

option(SUBDIV_WITH_MPI "Spread `subdiv refine --pieces` over MPI ranks when MPI is found" ON)
set(SUBDIV_HAVE_MPI FALSE)
if(SUBDIV_WITH_MPI)
  find_package(MPI COMPONENTS CXX QUIET)
  if(MPI_CXX_FOUND)
    set(SUBDIV_HAVE_MPI TRUE)
    message(STATUS "MPI: ${MPI_CXX_LIBRARY_VERSION_STRING} (subdiv refine --pieces under mpirun)")
  else()
    message(STATUS "MPI not found: subdiv refine --pieces runs serially (install libopenmpi-dev for MPI)")
  endif()
endif()
