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

namespace subdiv_test {

// Under the sanitizers the suite runs about ten times slower than in Release. Sweeps that
// repeat one check over many like inputs (shapes' faces, crease lengths, piece counts) keep
// every kSanitizerThinning-th input there: the same code paths, fewer repetitions, so that
// CI's sanitizer stage stays within its time. The Release run takes every input.
inline constexpr int kSanitizerThinning = SUBDIV_TEST_ASAN ? 3 : 1;

// True when a sweep's i-th input is left out under the sanitizers.
constexpr bool thinned_out(long i) { return i % kSanitizerThinning != 0; }

}  // namespace subdiv_test
