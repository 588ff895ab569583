// Invariants of lancer's own data, which bad input cannot break (input is checked where it comes
// in): LANCER_DCHECK(a, op, b), as pbrt-v4's CHECK_EQ and friends, prints the comparison, both
// values and the place, then aborts. Compiled in with LANCER_DCHECKS (Debug and sanitizer builds);
// release builds do not evaluate the operands.
#pragma once

#include <sstream>
#include <string>

namespace lancer {

[[noreturn]] void dcheckFailed(const char* expression, const std::string& values, const char* file, int line);

template <typename A, typename B>
std::string dcheckValues(const A& a, const B& b) {
  std::ostringstream out;
  out << a << " vs " << b;
  return out.str();
}

}  // namespace lancer

#if defined(LANCER_DCHECKS)
#define LANCER_DCHECK(a, op, b)                                                                     \
  do {                                                                                              \
    const auto& lancerCheckA = (a);                                                                 \
    const auto& lancerCheckB = (b);                                                                 \
    if (!(lancerCheckA op lancerCheckB))                                                            \
      ::lancer::dcheckFailed(#a " " #op " " #b, ::lancer::dcheckValues(lancerCheckA, lancerCheckB), \
                             __FILE__, __LINE__);                                                   \
  } while (false)
#else
#define LANCER_DCHECK(a, op, b) \
  do {                          \
  } while (false)
#endif
