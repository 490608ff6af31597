# Sanitizer and fuzzing builds (scripts/sanitize.sh, scripts/fuzz.sh; docs/testing.md).
#
# SUBDIV_SANITIZE=ON: everything, the library, tools, plugins and tests, with AddressSanitizer
# and UndefinedBehaviorSanitizer; any UB report aborts (-fno-sanitize-recover) so that ctest
# sees it as a failure.
# SUBDIV_BUILD_FUZZERS=ON (clang only): additionally coverage instrumentation for libFuzzer
# everywhere and the harnesses in tests/fuzz. The instrumentation does not change what the
# test executables do, so one build directory serves the sanitized test suite and the
# fuzzers and CI builds the library once for both.
option(SUBDIV_SANITIZE "Build with AddressSanitizer and UndefinedBehaviorSanitizer" OFF)
option(SUBDIV_BUILD_FUZZERS "Build the libFuzzer harnesses in tests/fuzz (clang; implies SUBDIV_SANITIZE)" OFF)

if(SUBDIV_BUILD_FUZZERS)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "SUBDIV_BUILD_FUZZERS needs clang (libFuzzer): configure with "
                        "-DCMAKE_CXX_COMPILER=clang++-14, as scripts/fuzz.sh does")
  endif()
  set(SUBDIV_SANITIZE ON CACHE BOOL "" FORCE)
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()

if(SUBDIV_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined -fno-sanitize-recover=undefined)
endif()
