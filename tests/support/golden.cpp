#include "support/golden.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <system_error>
#include <vector>

#include "lancer/image/image_io.hpp"
#include "lancer/util/input_error.hpp"

namespace lancer::test {
namespace {

constexpr int kDifferenceGain = 8;

std::filesystem::path failureFolder() {
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::string testName =
      info != nullptr ? fmt::format("{}.{}", info->test_suite_name(), info->name()) : std::string("no-test");
  std::string sanitized;
  for (char c : testName)
    sanitized += (std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_') ? c : '_';
  std::vector<std::filesystem::path> candidates;
  if (const char* dir = std::getenv("LANCER_GOLDEN_FAILURE_DIR")) candidates.emplace_back(dir);
  candidates.push_back(std::filesystem::current_path() / "golden-failures");
  candidates.emplace_back("/tmp/lancer-golden-failures");
  for (const std::filesystem::path& base : candidates) {
    std::error_code error;
    const std::filesystem::path folder = base / sanitized;
    std::filesystem::create_directories(folder, error);
    if (!error && ::access(folder.c_str(), W_OK) == 0) return folder;
  }
  return std::filesystem::temp_directory_path();
}

Image differenceImage(const Image& a, const Image& b, TransferCurve curve) {
  Image out(a.width(), a.height());
  auto channel = [&](float x, float y) {
    const int d = std::abs(int{encode8(x, curve)} - int{encode8(y, curve)}) * kDifferenceGain;
    return static_cast<float>(std::min(d, 255)) / 255.0f;
  };
  for (int y = 0; y < a.height(); ++y) {
    for (int x = 0; x < a.width(); ++x) {
      const Rgba& p = a.at(x, y);
      const Rgba& q = b.at(x, y);
      out.at(x, y) = {channel(p.r, q.r), channel(p.g, q.g), channel(p.b, q.b), 1.0f};
    }
  }
  return out;
}

}  // namespace

double psnr8(const Image& a, const Image& b, TransferCurve curve) {
  if (a.width() != b.width() || a.height() != b.height()) return -std::numeric_limits<double>::infinity();
  const bool withAlpha = a.hasTransparency() || b.hasTransparency();
  double squaredError = 0;
  std::size_t samples = 0;
  for (std::size_t i = 0; i < a.pixels().size(); ++i) {
    const Rgba& p = a.pixels()[i];
    const Rgba& q = b.pixels()[i];
    auto add = [&](std::uint8_t x, std::uint8_t y) {
      const double d = static_cast<double>(x) - static_cast<double>(y);
      squaredError += d * d;
      ++samples;
    };
    add(encode8(p.r, curve), encode8(q.r, curve));
    add(encode8(p.g, curve), encode8(q.g, curve));
    add(encode8(p.b, curve), encode8(q.b, curve));
    if (withAlpha) add(encode8(p.a), encode8(q.a));
  }
  if (squaredError == 0 || samples == 0) return std::numeric_limits<double>::infinity();
  return 10.0 * std::log10(255.0 * 255.0 / (squaredError / static_cast<double>(samples)));
}

bool updatingGoldenFiles() {
  const char* value = std::getenv("LANCER_UPDATE_GOLDEN");
  return value != nullptr && std::string(value) == "1";
}

void expectImageNear(const Image& actual, const std::string& expectedPngPath, double minPsnrDb,
                     TransferCurve curve) {
  ImageWriteOptions options;
  options.curve = curve;
  if (updatingGoldenFiles()) {
    writePng(expectedPngPath, actual, options);
    std::printf("[ golden   ] updated %s\n", expectedPngPath.c_str());
    return;
  }
  const std::filesystem::path folder = failureFolder();
  const std::string actualPath = (folder / "actual.png").string();
  Image expected;
  try {
    expected = readPng(expectedPngPath, curve);
  } catch (const InputError& e) {
    writePng(actualPath, actual, options);
    ADD_FAILURE() << "cannot read the golden image: " << e.what() << "\n  actual: " << actualPath
                  << "\n  to create it, run the test with LANCER_UPDATE_GOLDEN=1";
    return;
  }
  if (expected.width() != actual.width() || expected.height() != actual.height()) {
    writePng(actualPath, actual, options);
    ADD_FAILURE() << "size differs from the golden image " << expectedPngPath << ": actual " << actual.width()
                  << "x" << actual.height() << ", expected " << expected.width() << "x" << expected.height()
                  << "\n  actual: " << actualPath;
    return;
  }
  const double psnr = psnr8(actual, expected, curve);
  if (psnr >= minPsnrDb) return;
  const std::string expectedPath = (folder / "expected.png").string();
  const std::string differencePath = (folder / "difference.png").string();
  writePng(actualPath, actual, options);
  writePng(expectedPath, expected, options);
  writePng(differencePath, differenceImage(actual, expected, curve));
  ADD_FAILURE() << fmt::format(
      "image differs from the golden image {}: PSNR {:.2f} dB < {:.2f} dB\n  actual:     {}\n  expected:   "
      "{}\n"
      "  difference: {} (|actual - expected| x {})",
      expectedPngPath, psnr, minPsnrDb, actualPath, expectedPath, differencePath, kDifferenceGain);
}

}  // namespace lancer::test
