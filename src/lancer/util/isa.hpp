// Which instruction set the hot kernels run with: one binary for every x86-64 CPU, fast on AVX2.
// The library is built for baseline x86-64 (or the compiler's default elsewhere); the few sources
// whose loops gain from AVX2 and FMA (the trees' traversals, the face normals; KernelSources in
// src/lancer/CMakeLists.txt) are built a second time for x86-64-v3, each copy in a namespace of its
// own (LANCER_ISA_NS), and the caller picks one copy per query by the CPU it runs on. Nothing outside
// those copies holds an AVX2 instruction, so a CPU without it never meets one (docs/hardening.md).
#pragma once

namespace lancer::isa {

// Tags naming the kernels' copies: the build's own instruction set, and x86-64-v3 (AVX2, FMA, BMI2).
struct Baseline {};
struct X86_64_V3 {};

// Whether the x86-64-v3 copies are in this build (x86-64 without LANCER_PORTABLE).
#if defined(LANCER_HAVE_X86_64_V3_KERNELS)
inline constexpr bool kHaveX86_64_V3 = true;
#else
inline constexpr bool kHaveX86_64_V3 = false;
#endif

// Whether this process runs the x86-64-v3 copies: the CPU has every feature of the level (and the
// system saves the AVX registers), and LANCER_ISA is not "baseline" (an environment variable, to run
// the other copy on the same machine: tests compare the two pictures). Decided once per process.
bool detectX86_64_V3();
inline bool useX86_64_V3() {
  if constexpr (!kHaveX86_64_V3) {
    return false;
  } else {
    static const bool use = detectX86_64_V3();
    return use;
  }
}

// Calls `kernel` with the tag of the copy to run.
template <typename Kernel>
decltype(auto) dispatch(Kernel&& kernel) {
  if constexpr (kHaveX86_64_V3) {
    if (useX86_64_V3()) return kernel(X86_64_V3{});
  }
  return kernel(Baseline{});
}

}  // namespace lancer::isa

// In a kernel source: the namespace and tag of the copy being compiled (CMake defines
// LANCER_ISA_X86_64_V3 for the second copy). Inline functions of the kernels' headers live in
// lancer::...::LANCER_ISA_NS, so that the two copies never share a symbol the linker could merge.
#if defined(LANCER_ISA_X86_64_V3)
#define LANCER_ISA_NS x86_64_v3
#define LANCER_ISA_TAG ::lancer::isa::X86_64_V3
#else
#define LANCER_ISA_NS baseline
#define LANCER_ISA_TAG ::lancer::isa::Baseline
#endif
