// One binary for every x86-64 CPU (util/isa.hpp): the baseline copy of the hot kernels draws the
// picture the x86-64-v3 copy draws (within the render goldens' PSNR floor), chosen on this machine
// with LANCER_ISA=baseline, and the whole program runs on a CPU without AVX2: the CLI and the Python
// module under qemu-x86_64 -cpu Westmere (Debian's qemu-user), skipped where qemu is not installed.
#include "lancer/util/isa.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <string>

#include "lancer/image/image_io.hpp"
#include "support/cli.hpp"
#include "support/files.hpp"
#include "support/golden.hpp"
#include "support/instrumented.hpp"
#include "support/scoped_env.hpp"

namespace lancer {
namespace {

using test::quoted;

// A small render that goes through both kernels: smooth normals (face terms) and the BVH's packets
// and single rays (shadows).
std::string renderArguments(const std::string& output) {
  return fmt::format("render {} --width 64 --height 48 -q -o {}",
                     quoted(std::string(LANCER_SOURCE_DIR) + "/examples/meshes/sphere.msh"), quoted(output));
}

// A CPU of 2010 (SSE4.2, no AVX): what x86-64 without x86-64-v3 looks like.
constexpr const char* kOldCpu = "qemu-x86_64 -cpu Westmere";

bool qemuInstalled() { return test::runShell("command -v qemu-x86_64 >/dev/null 2>&1").exitCode == 0; }

#if defined(__x86_64__)
constexpr bool kX86_64 = true;
#else
constexpr bool kX86_64 = false;
#endif

TEST(Isa, LancerIsaBaselineTurnsTheX86_64_V3KernelsOff) {
  test::ScopedEnv baseline("LANCER_ISA", "baseline");
  EXPECT_FALSE(isa::detectX86_64_V3());
}

TEST(Isa, NoX86_64_V3KernelsWithoutTheirCopy) {
  if (!isa::kHaveX86_64_V3) {
    EXPECT_FALSE(isa::useX86_64_V3());
  }
}

TEST(Isa, BaselineKernelsDrawTheX86_64_V3Picture) {
  if (!isa::kHaveX86_64_V3 || !isa::detectX86_64_V3())
    GTEST_SKIP() << "no x86-64-v3 kernels on this build or CPU";
  const test::ScratchFolder folder;
  const auto fast = test::runCli(renderArguments(folder.file("v3.png")));
  ASSERT_EQ(fast.exitCode, 0) << fast.output;
  const auto baseline = test::runCli(renderArguments(folder.file("baseline.png")), "LANCER_ISA=baseline");
  ASSERT_EQ(baseline.exitCode, 0) << baseline.output;
  const double psnr = test::psnr8(readPng(folder.file("v3.png")), readPng(folder.file("baseline.png")));
  EXPECT_GE(psnr, test::kRenderGoldenMinPsnrDb);
}

TEST(Isa, CliRunsOnACpuWithoutAvx2) {
  if (!kX86_64) GTEST_SKIP() << "not an x86-64 build";
  if (!qemuInstalled()) GTEST_SKIP() << "qemu-x86_64 not installed (Debian: qemu-user)";
  // A sanitizer's shadow memory does not fit qemu-user's address space; the release build is checked.
  if (test::kInstrumented) GTEST_SKIP() << "a sanitizer build (qemu cannot run it)";
  const auto version = test::runCli("--version", kOldCpu);
  ASSERT_EQ(version.exitCode, 0) << version.output;  // 132 (SIGILL) before the kernels had two copies
  EXPECT_TRUE(test::contains(version.output, "lancer ")) << version.output;

  const test::ScratchFolder folder;
  const auto native = test::runCli(renderArguments(folder.file("native.png")));
  ASSERT_EQ(native.exitCode, 0) << native.output;
  const auto old = test::runCli(renderArguments(folder.file("westmere.png")), kOldCpu);
  ASSERT_EQ(old.exitCode, 0) << old.output;
  const double psnr = test::psnr8(readPng(folder.file("native.png")), readPng(folder.file("westmere.png")));
  EXPECT_GE(psnr, test::kRenderGoldenMinPsnrDb);
}

#if defined(LANCER_TEST_PYTHON_PACKAGE_DIR)
TEST(Isa, PythonModuleImportsOnACpuWithoutAvx2) {
  if (!kX86_64) GTEST_SKIP() << "not an x86-64 build";
  if (!qemuInstalled()) GTEST_SKIP() << "qemu-x86_64 not installed (Debian: qemu-user)";
  // A sanitizer's shadow memory does not fit qemu-user's address space; the release build is checked.
  if (test::kInstrumented) GTEST_SKIP() << "a sanitizer build (qemu cannot run it)";
  // The interpreter runs under qemu too, so the extension is loaded (its static initialisers run) and
  // used on the old CPU; a kernel crash would kill the interpreter (exit 132).
  const std::string script = "import lancer; m = lancer.read_msh(" +
                             quoted(std::string(LANCER_SOURCE_DIR) + "/examples/meshes/glass_block.msh") +
                             "); print(lancer.render(m, width=16, height=12).shape)";
  const auto run = test::runShell(fmt::format("PYTHONPATH={} PYTHONDONTWRITEBYTECODE=1 {} {} -c \"{}\" 2>&1",
                                              quoted(LANCER_TEST_PYTHON_PACKAGE_DIR), kOldCpu,
                                              LANCER_TEST_PYTHON, script));
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_TRUE(test::contains(run.output, "(12, 16, 3)")) << run.output;
}
#endif

}  // namespace
}  // namespace lancer
