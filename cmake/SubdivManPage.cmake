# subdiv.1.gz from the program's own help (cmake -P; cmake/SubdivPackaging.cmake runs it):
# help2man over `subdiv --help`, with each command's `subdiv COMMAND --help` as a section.
# -DSUBDIV=<program> -DHELP2MAN=<help2man> -DVERSION=<x.y.z> -DOUT=<dir>
set(ENV{SUBDIV_NO_INSTALLED_PLUGINS} 1)  # the help of this build, whatever is installed
execute_process(COMMAND ${SUBDIV} --help OUTPUT_VARIABLE help RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${SUBDIV} --help failed")
endif()
# The commands: the lines under "Subcommands:" of the main help.
string(REGEX MATCH "Subcommands:\n(.*)" block "${help}")
set(include "[COMMANDS]\n")
string(REGEX MATCHALL "(^|\n)  [a-z]+ " names "${CMAKE_MATCH_1}")
foreach(entry IN LISTS names)
  string(STRIP "${entry}" command)
  execute_process(COMMAND ${SUBDIV} ${command} --help OUTPUT_VARIABLE text RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${SUBDIV} ${command} --help failed")
  endif()
  string(REPLACE "${SUBDIV}" "subdiv" text "${text}")  # the usage line names the program by its path
  # roff: a leading '.' or '\'' would be a request; backslashes escaped.
  string(REPLACE "\\" "\\e" text "${text}")
  string(REGEX REPLACE "\n([.'])" "\n\\\\&\\1" text "${text}")
  string(APPEND include ".SS \"subdiv ${command}\"\n.nf\n${text}.fi\n")
endforeach()
file(MAKE_DIRECTORY ${OUT})
file(WRITE ${OUT}/subdiv.h2m "${include}")
execute_process(COMMAND ${HELP2MAN} --no-info --no-discard-stderr --section 1
                        --name "define, run and analyse subdivision schemes"
                        --version-string "subdiv ${VERSION}" --include ${OUT}/subdiv.h2m
                        --output ${OUT}/subdiv.1 ${SUBDIV}
                RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "help2man failed")
endif()
file(REMOVE ${OUT}/subdiv.1.gz)
execute_process(COMMAND gzip -9n ${OUT}/subdiv.1 RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "gzip failed")
endif()
