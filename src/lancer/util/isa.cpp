#include "lancer/util/isa.hpp"

#include <cstdlib>
#include <cstring>

#if defined(__x86_64__)
#include <cpuid.h>
#endif

namespace lancer::isa {

namespace {

#if defined(__x86_64__)
// x86-64-v3 as the psABI defines it (what -march=x86-64-v3 may use): AVX, AVX2, BMI1, BMI2, F16C,
// FMA, LZCNT, MOVBE, XSAVE, with the OS saving the SSE and AVX registers (XCR0 bits 1 and 2). Read
// from CPUID directly: the same answer from GCC and clang, whose __builtin_cpu_supports differ.
bool cpuHasX86_64_V3() {
  unsigned a, b, c, d;
  if (!__get_cpuid(1, &a, &b, &c, &d)) return false;
  const bool fma = c >> 12 & 1, movbe = c >> 22 & 1, osxsave = c >> 27 & 1, avx = c >> 28 & 1,
             f16c = c >> 29 & 1;
  if (!(fma && movbe && osxsave && avx && f16c)) return false;
  unsigned xcr0Low, xcr0High;
  __asm__("xgetbv" : "=a"(xcr0Low), "=d"(xcr0High) : "c"(0));
  if ((xcr0Low & 0x6u) != 0x6u) return false;
  if (!__get_cpuid_count(7, 0, &a, &b, &c, &d)) return false;
  const bool bmi1 = b >> 3 & 1, avx2 = b >> 5 & 1, bmi2 = b >> 8 & 1;
  if (!(bmi1 && avx2 && bmi2)) return false;
  if (!__get_cpuid(0x80000001u, &a, &b, &c, &d)) return false;
  return (c >> 5 & 1) != 0;  // LZCNT (ABM)
}
#endif

}  // namespace

bool detectX86_64_V3() {
#if defined(__x86_64__)
  if (!cpuHasX86_64_V3()) return false;
  const char* forced = std::getenv("LANCER_ISA");
  return forced == nullptr || std::strcmp(forced, "baseline") != 0;
#else
  return false;
#endif
}

}  // namespace lancer::isa
