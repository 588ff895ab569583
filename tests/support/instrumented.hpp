// Whether the tests run in a sanitizer build (ASan + UBSan, TSan, libFuzzer's coverage): the code runs
// five to ten times slower there, and what it checks is memory and threads, not answers. The property
// tests' thousands of random rays are cut to a quarter there; the plain build runs them all (CI runs
// both), and every code path they reach is still reached.
#pragma once

#include <algorithm>

namespace lancer::test {

#if defined(LANCER_TEST_INSTRUMENTED) && LANCER_TEST_INSTRUMENTED
inline constexpr bool kInstrumented = true;
#else
inline constexpr bool kInstrumented = false;
#endif

// How many random cases a property test runs: `count`, a quarter of it in a sanitizer build.
inline int propertyCount(int count) { return kInstrumented ? std::max(1, count / 4) : count; }

}  // namespace lancer::test
