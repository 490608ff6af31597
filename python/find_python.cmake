# Finds what the `subdivkit` Python module needs: Debian's python3 with its headers and
# NumPy, and pybind11. Sets SUBDIV_PYTHON_FOUND; when something is missing the module is
# skipped with a note saying which package to install, and the rest of the build goes on.
#
# Debian's /usr/bin/python3 is preferred over whatever comes first on PATH (a pyenv python,
# say): the module is installed into Debian's dist-packages and must match its ABI.
# Pass -DPython3_EXECUTABLE=... to build for another interpreter.
if(NOT Python3_EXECUTABLE AND EXISTS /usr/bin/python3)
  set(Python3_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "Python interpreter the subdivkit module is built for")
endif()
find_package(Python3 COMPONENTS Interpreter Development.Module NumPy)
find_package(pybind11 2.6 CONFIG QUIET)
set(SUBDIV_PYTHON_FOUND OFF)
if(NOT Python3_FOUND)
  message(STATUS "subdivkit Python module: skipped (install python3-dev and python3-numpy)")
elseif(NOT pybind11_FOUND)
  message(STATUS "subdivkit Python module: skipped (install pybind11-dev)")
else()
  set(SUBDIV_PYTHON_FOUND ON)
  message(STATUS "subdivkit Python module: for ${Python3_EXECUTABLE} (Python ${Python3_VERSION}), pybind11 ${pybind11_VERSION}")
endif()
