// LANCER_DCHECK: in builds with LANCER_DCHECKS (Debug, the sanitizer build) a failed invariant
// names the comparison, both values and the place, then aborts; elsewhere it evaluates nothing.
#include "lancer/util/check.hpp"

#include <gtest/gtest.h>

namespace lancer {
namespace {

TEST(Check, AFailedInvariantNamesTheComparisonAndBothValues) {
#if defined(LANCER_DCHECKS)
  const int faces = 3, materials = 2;
  LANCER_DCHECK(faces, >, materials);  // holds: nothing happens
  EXPECT_DEATH(LANCER_DCHECK(faces, ==, materials), "check faces == materials failed \\(3 vs 2\\)");
#else
  int evaluated = 0;
  LANCER_DCHECK(++evaluated, ==, 2);
  EXPECT_EQ(evaluated, 0);  // compiled away: the operands are not evaluated
#endif
}

}  // namespace
}  // namespace lancer
