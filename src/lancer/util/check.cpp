#include "lancer/util/check.hpp"

#include <cstdio>
#include <cstdlib>

namespace lancer {

void dcheckFailed(const char* expression, const std::string& values, const char* file, int line) {
  std::fprintf(stderr, "%s:%d: internal error: check %s failed (%s)\n", file, line, expression,
               values.c_str());
  std::abort();
}

}  // namespace lancer
