#pragma once
// SUBDIV_TEST_ASAN is 1 when the tests are built with AddressSanitizer (GCC says so with
// __SANITIZE_ADDRESS__, clang with __has_feature). ASan reserves terabytes of address
// space for its shadow memory, so tests that set ulimit -v or RLIMIT_DATA skip themselves.
#if defined(__SANITIZE_ADDRESS__)
#define SUBDIV_TEST_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SUBDIV_TEST_ASAN 1
#endif
#endif
#ifndef SUBDIV_TEST_ASAN
#define SUBDIV_TEST_ASAN 0
#endif
