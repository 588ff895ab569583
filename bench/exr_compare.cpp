// Compares linear EXR renders for bench/cycles_compare.sh (lancer against Blender Cycles):
//   exr_compare stats A.exr                   size and the mean of R, G, B
//   exr_compare diff TEST.exr REF.exr [GRID]  RMSE over every pixel and channel (linear values, no clamp),
//                                             the channel means, and per region of a GRID x GRID split
//                                             (default 4) the mean difference against its standard
//                                             error: a |z| far above 3 is a bias, not noise
//   exr_compare average OUT.exr IN.exr...     the pixel mean of renders with different seeds
#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

#include "lancer/image/exr_io.hpp"

namespace {

using namespace lancer;

Vec3 meanOf(const Image& image) {
  Vec3 sum{0, 0, 0};
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) sum += image.at(x, y).rgb();
  return sum * (1.0f / static_cast<float>(image.width() * image.height()));
}

int stats(const std::string& path) {
  const Image image = readExr(path);
  const Vec3 mean = meanOf(image);
  fmt::print("{}: {}x{}, mean R G B {:.5f} {:.5f} {:.5f}\n", path, image.width(), image.height(), mean.x,
             mean.y, mean.z);
  return 0;
}

int diff(const std::string& testPath, const std::string& refPath, int grid) {
  const Image test = readExr(testPath), ref = readExr(refPath);
  if (test.width() != ref.width() || test.height() != ref.height()) {
    fmt::print(stderr, "{} is {}x{}, {} is {}x{}\n", testPath, test.width(), test.height(), refPath,
               ref.width(), ref.height());
    return 2;
  }
  double squares = 0;
  // Per region: sum and sum of squares of the per-pixel difference of the channel mean.
  std::vector<double> sum(static_cast<std::size_t>(grid * grid)), sum2(sum.size()), refSum(sum.size());
  std::vector<int> count(sum.size());
  for (int y = 0; y < test.height(); ++y)
    for (int x = 0; x < test.width(); ++x) {
      const Vec3 a = test.at(x, y).rgb(), b = ref.at(x, y).rgb(), d = a - b;
      squares += dot(d, d);
      const std::size_t cell =
          static_cast<std::size_t>(y * grid / test.height() * grid + x * grid / test.width());
      const double m = (d.x + d.y + d.z) / 3.0;
      sum[cell] += m;
      sum2[cell] += m * m;
      refSum[cell] += (b.x + b.y + b.z) / 3.0;
      ++count[cell];
    }
  const double pixels = static_cast<double>(test.width()) * test.height();
  const Vec3 mt = meanOf(test), mr = meanOf(ref);
  fmt::print("RMSE {:.6f}\n", std::sqrt(squares / (3.0 * pixels)));
  fmt::print(
      "mean R G B test {:.5f} {:.5f} {:.5f}, reference {:.5f} {:.5f} {:.5f}, ratio {:.4f} {:.4f} {:.4f}\n",
      mt.x, mt.y, mt.z, mr.x, mr.y, mr.z, mt.x / mr.x, mt.y / mr.y, mt.z / mr.z);
  fmt::print(
      "regions (rows top to bottom): mean test/reference - 1 [z = mean difference / standard error]\n");
  for (int gy = 0; gy < grid; ++gy) {
    for (int gx = 0; gx < grid; ++gx) {
      const std::size_t c = static_cast<std::size_t>(gy * grid + gx);
      const double n = count[c], mean = sum[c] / n;
      const double error = std::sqrt(std::max(sum2[c] / n - mean * mean, 0.0) / n);
      fmt::print("  {:+.4f} [{:+6.1f}]", mean / (refSum[c] / n), error > 0 ? mean / error : 0.0);
    }
    fmt::print("\n");
  }
  return 0;
}

int average(const std::string& outPath, const std::vector<std::string>& inputs) {
  Image mean = readExr(inputs.front());
  for (std::size_t i = 1; i < inputs.size(); ++i) {
    const Image next = readExr(inputs[i]);
    for (int y = 0; y < mean.height(); ++y)
      for (int x = 0; x < mean.width(); ++x) {
        Rgba& p = mean.at(x, y);
        const Rgba& q = next.at(x, y);
        p.r += q.r;
        p.g += q.g;
        p.b += q.b;
      }
  }
  const float scale = 1.0f / static_cast<float>(inputs.size());
  for (int y = 0; y < mean.height(); ++y)
    for (int x = 0; x < mean.width(); ++x) {
      Rgba& p = mean.at(x, y);
      p.r *= scale;
      p.g *= scale;
      p.b *= scale;
      p.a = 1.0f;
    }
  writeExr(outPath, mean);
  fmt::print("{}: the mean of {} images\n", outPath, inputs.size());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  try {
    if (args.size() == 2 && args[0] == "stats") return stats(args[1]);
    if ((args.size() == 3 || args.size() == 4) && args[0] == "diff")
      return diff(args[1], args[2], args.size() == 4 ? std::max(1, std::atoi(args[3].c_str())) : 4);
    if (args.size() >= 3 && args[0] == "average")
      return average(args[1], std::vector<std::string>(args.begin() + 2, args.end()));
  } catch (const std::exception& e) {
    fmt::print(stderr, "{}\n", e.what());
    return 1;
  }
  fmt::print(stderr,
             "usage: exr_compare stats A.exr | diff TEST.exr REF.exr [GRID] | average OUT.exr IN.exr...\n");
  return 2;
}
