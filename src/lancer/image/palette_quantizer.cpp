#include "lancer/image/palette_quantizer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace lancer {
namespace {

constexpr int kSide = 33;  // 32 cells per channel plus the empty index 0
constexpr std::size_t kCells = kSide * kSide * kSide;

constexpr std::size_t cell(int r, int g, int b) {
  constexpr auto side = static_cast<std::size_t>(kSide);
  return (static_cast<std::size_t>(r) * side + static_cast<std::size_t>(g)) * side +
         static_cast<std::size_t>(b);
}

constexpr std::uint32_t pack(int r, int g, int b) {
  return (static_cast<std::uint32_t>(r) << 16) | (static_cast<std::uint32_t>(g) << 8) |
         static_cast<std::uint32_t>(b);
}

// A box of histogram cells: r0 < r <= r1 (likewise g, b), as in Wu's paper.
struct Box {
  int r0 = 0, r1 = 0, g0 = 0, g1 = 0, b0 = 0, b1 = 0;
  int volume() const { return (r1 - r0) * (g1 - g0) * (b1 - b0); }
};

// Cumulative moments: after accumulate(), m[cell(r,g,b)] sums all cells <= (r, g, b).
template <typename T>
void accumulate(std::vector<T>& m) {
  for (int r = 1; r < kSide; ++r) {
    std::array<T, kSide> area{};
    for (int g = 1; g < kSide; ++g) {
      T line = 0;
      for (int b = 1; b < kSide; ++b) {
        line += m[cell(r, g, b)];
        area[static_cast<std::size_t>(b)] += line;
        m[cell(r, g, b)] = m[cell(r - 1, g, b)] + area[static_cast<std::size_t>(b)];
      }
    }
  }
}

template <typename T>
T volume(const Box& c, const std::vector<T>& m) {
  return m[cell(c.r1, c.g1, c.b1)] - m[cell(c.r1, c.g1, c.b0)] - m[cell(c.r1, c.g0, c.b1)] +
         m[cell(c.r1, c.g0, c.b0)] - m[cell(c.r0, c.g1, c.b1)] + m[cell(c.r0, c.g1, c.b0)] +
         m[cell(c.r0, c.g0, c.b1)] - m[cell(c.r0, c.g0, c.b0)];
}

// The sum over the box's face below the plane axis = position (the part removed by "bottom").
template <typename T>
T bottom(const Box& c, int axis, const std::vector<T>& m) {
  switch (axis) {
    case 0:
      return -m[cell(c.r0, c.g1, c.b1)] + m[cell(c.r0, c.g1, c.b0)] + m[cell(c.r0, c.g0, c.b1)] -
             m[cell(c.r0, c.g0, c.b0)];
    case 1:
      return -m[cell(c.r1, c.g0, c.b1)] + m[cell(c.r1, c.g0, c.b0)] + m[cell(c.r0, c.g0, c.b1)] -
             m[cell(c.r0, c.g0, c.b0)];
    default:
      return -m[cell(c.r1, c.g1, c.b0)] + m[cell(c.r1, c.g0, c.b0)] + m[cell(c.r0, c.g1, c.b0)] -
             m[cell(c.r0, c.g0, c.b0)];
  }
}

template <typename T>
T top(const Box& c, int axis, int position, const std::vector<T>& m) {
  switch (axis) {
    case 0:
      return m[cell(position, c.g1, c.b1)] - m[cell(position, c.g1, c.b0)] - m[cell(position, c.g0, c.b1)] +
             m[cell(position, c.g0, c.b0)];
    case 1:
      return m[cell(c.r1, position, c.b1)] - m[cell(c.r1, position, c.b0)] - m[cell(c.r0, position, c.b1)] +
             m[cell(c.r0, position, c.b0)];
    default:
      return m[cell(c.r1, c.g1, position)] - m[cell(c.r1, c.g0, position)] - m[cell(c.r0, c.g1, position)] +
             m[cell(c.r0, c.g0, position)];
  }
}

struct Moments {
  const std::vector<std::int64_t>& w;
  const std::vector<std::int64_t>& r;
  const std::vector<std::int64_t>& g;
  const std::vector<std::int64_t>& b;
  const std::vector<double>& m2;

  // Sum of squared distances to the box mean (Wu's "Var").
  double variance(const Box& c) const {
    const double dr = static_cast<double>(volume(c, r));
    const double dg = static_cast<double>(volume(c, g));
    const double db = static_cast<double>(volume(c, b));
    const double dw = static_cast<double>(volume(c, w));
    return dw > 0 ? volume(c, m2) - (dr * dr + dg * dg + db * db) / dw : 0.0;
  }
};

struct CutChoice {
  double score = -1;
  int position = -1;
};

// The cut along `axis` maximising the between-box sum |mean|^2 * weight (Wu's "Maximize").
CutChoice bestCut(const Box& c, int axis, const Moments& m, double wholeR, double wholeG, double wholeB,
                  double wholeW) {
  const int first = (axis == 0 ? c.r0 : axis == 1 ? c.g0 : c.b0) + 1;
  const int last = axis == 0 ? c.r1 : axis == 1 ? c.g1 : c.b1;
  const double baseR = static_cast<double>(bottom(c, axis, m.r));
  const double baseG = static_cast<double>(bottom(c, axis, m.g));
  const double baseB = static_cast<double>(bottom(c, axis, m.b));
  const double baseW = static_cast<double>(bottom(c, axis, m.w));
  CutChoice best;
  for (int i = first; i < last; ++i) {
    const double lowR = baseR + static_cast<double>(top(c, axis, i, m.r));
    const double lowG = baseG + static_cast<double>(top(c, axis, i, m.g));
    const double lowB = baseB + static_cast<double>(top(c, axis, i, m.b));
    const double lowW = baseW + static_cast<double>(top(c, axis, i, m.w));
    if (lowW <= 0) continue;
    const double highW = wholeW - lowW;
    if (highW <= 0) continue;
    const double highR = wholeR - lowR, highG = wholeG - lowG, highB = wholeB - lowB;
    const double score = (lowR * lowR + lowG * lowG + lowB * lowB) / lowW +
                         (highR * highR + highG * highG + highB * highB) / highW;
    if (score > best.score) best = {score, i};
  }
  return best;
}

bool cut(Box& a, Box& b, const Moments& m) {
  const double wholeR = static_cast<double>(volume(a, m.r));
  const double wholeG = static_cast<double>(volume(a, m.g));
  const double wholeB = static_cast<double>(volume(a, m.b));
  const double wholeW = static_cast<double>(volume(a, m.w));
  std::array<CutChoice, 3> choices;
  for (int axis = 0; axis < 3; ++axis)
    choices[static_cast<std::size_t>(axis)] = bestCut(a, axis, m, wholeR, wholeG, wholeB, wholeW);
  int axis = 0;
  for (int k = 1; k < 3; ++k) {
    if (choices[static_cast<std::size_t>(k)].score > choices[static_cast<std::size_t>(axis)].score) axis = k;
  }
  const int position = choices[static_cast<std::size_t>(axis)].position;
  if (position < 0) return false;  // a single non-empty plane: nothing to split
  b = a;
  if (axis == 0) a.r1 = b.r0 = position;
  if (axis == 1) a.g1 = b.g0 = position;
  if (axis == 2) a.b1 = b.b0 = position;
  return true;
}

}  // namespace

PaletteBuilder::PaletteBuilder(int maxColours)
    : maxColours_(maxColours),
      weight_(kCells),
      sumR_(kCells),
      sumG_(kCells),
      sumB_(kCells),
      sumSquares_(kCells) {
  if (maxColours < 1 || maxColours > 256) throw std::invalid_argument("palette size outside 1..256");
}

void PaletteBuilder::add(std::span<const std::uint8_t> rgb) {
  std::uint32_t previous = 0xffffffffu;
  for (std::size_t i = 0; i + 2 < rgb.size(); i += 3) {
    const int r = rgb[i], g = rgb[i + 1], b = rgb[i + 2];
    const std::size_t c = cell((r >> 3) + 1, (g >> 3) + 1, (b >> 3) + 1);
    weight_[c] += 1;
    sumR_[c] += r;
    sumG_[c] += g;
    sumB_[c] += b;
    sumSquares_[c] += static_cast<double>(r * r + g * g + b * b);
    const std::uint32_t packed = pack(r, g, b);
    if (fewColours_ && packed != previous) {
      distinct_.insert(packed);
      previous = packed;
      if (distinct_.size() > static_cast<std::size_t>(maxColours_)) {
        fewColours_ = false;
        distinct_.clear();
      }
    }
  }
}

Palette PaletteBuilder::build() const {
  Palette palette;
  if (fewColours_) {
    std::vector<std::uint32_t> colours(distinct_.begin(), distinct_.end());
    std::sort(colours.begin(), colours.end());
    for (std::uint32_t c : colours) {
      palette.push_back({static_cast<std::uint8_t>(c >> 16), static_cast<std::uint8_t>(c >> 8),
                         static_cast<std::uint8_t>(c)});
    }
    return palette;
  }
  std::vector<std::int64_t> w = weight_, r = sumR_, g = sumG_, b = sumB_;
  std::vector<double> m2 = sumSquares_;
  accumulate(w);
  accumulate(r);
  accumulate(g);
  accumulate(b);
  accumulate(m2);
  const Moments moments{w, r, g, b, m2};

  std::vector<Box> boxes(static_cast<std::size_t>(maxColours_));
  std::vector<double> splitGain(static_cast<std::size_t>(maxColours_), 0.0);
  boxes[0] = {0, kSide - 1, 0, kSide - 1, 0, kSide - 1};
  int count = 1;
  std::size_t next = 0;
  while (count < maxColours_) {
    Box& from = boxes[next];
    Box& to = boxes[static_cast<std::size_t>(count)];
    if (cut(from, to, moments)) {
      splitGain[next] = from.volume() > 1 ? moments.variance(from) : 0.0;
      splitGain[static_cast<std::size_t>(count)] = to.volume() > 1 ? moments.variance(to) : 0.0;
      ++count;
    } else {
      splitGain[next] = 0.0;
    }
    next = static_cast<std::size_t>(std::max_element(splitGain.begin(), splitGain.begin() + count) -
                                    splitGain.begin());
    if (splitGain[next] <= 0.0) break;
  }
  for (int k = 0; k < count; ++k) {
    const Box& box = boxes[static_cast<std::size_t>(k)];
    const double weight = static_cast<double>(volume(box, w));
    if (weight <= 0) continue;
    auto mean = [&](const std::vector<std::int64_t>& sum) {
      return static_cast<std::uint8_t>(
          std::clamp(std::lround(static_cast<double>(volume(box, sum)) / weight), 0L, 255L));
    };
    palette.push_back({mean(r), mean(g), mean(b)});
  }
  return palette;
}

Palette quantize(std::span<const std::uint8_t> rgb, int maxColours) {
  PaletteBuilder builder(maxColours);
  builder.add(rgb);
  return builder.build();
}

// Direct-mapped cache of recent lookups; a key is the packed colour with bit 24 set when valid.
constexpr std::size_t kCacheSize = std::size_t{1} << 15;

NearestColour::NearestColour(const Palette& palette)
    : palette_(palette), cacheKey_(kCacheSize, 0), cacheValue_(kCacheSize, 0) {
  if (palette.empty() || palette.size() > 256) throw std::invalid_argument("palette size outside 1..256");
  std::vector<std::uint8_t> order(palette.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<std::uint8_t>(i);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::uint8_t a, std::uint8_t b) { return palette[a].g < palette[b].g; });
  for (std::uint8_t i : order) {
    sorted_.push_back(palette[i]);
    sortedIndex_.push_back(i);
  }
}

std::uint8_t NearestColour::operator()(int r, int g, int b) {
  const std::uint32_t key = pack(r, g, b) | (1u << 24);
  const std::size_t slot = ((key * 2654435761u) >> 17) & (kCacheSize - 1);
  if (cacheKey_[slot] == key) return cacheValue_[slot];
  const std::uint8_t index = search(r, g, b);
  cacheKey_[slot] = key;
  cacheValue_[slot] = index;
  return index;
}

std::uint8_t NearestColour::search(int r, int g, int b) const {
  const auto start = std::lower_bound(sorted_.begin(), sorted_.end(), g,
                                      [](const Rgb8& c, int green) { return c.g < green; });
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(sorted_.size());
  std::ptrdiff_t up = start - sorted_.begin();
  std::ptrdiff_t down = up - 1;
  int bestDistance = 1 << 30;
  std::uint8_t best = 0;
  auto consider = [&](std::ptrdiff_t k) {
    const Rgb8& c = sorted_[static_cast<std::size_t>(k)];
    const int dr = c.r - r, dg = c.g - g, db = c.b - b;
    const int d = dr * dr + dg * dg + db * db;
    const std::uint8_t index = sortedIndex_[static_cast<std::size_t>(k)];
    if (d < bestDistance || (d == bestDistance && index < best)) {
      bestDistance = d;
      best = index;
    }
  };
  // Walk outwards in green; stop a direction once its green gap alone exceeds the best distance.
  while (up < n || down >= 0) {
    if (up < n) {
      const int dg = sorted_[static_cast<std::size_t>(up)].g - g;
      if (dg * dg > bestDistance) {
        up = n;
      } else {
        consider(up++);
      }
    }
    if (down >= 0) {
      const int dg = g - sorted_[static_cast<std::size_t>(down)].g;
      if (dg * dg > bestDistance) {
        down = -1;
      } else {
        consider(down--);
      }
    }
  }
  return best;
}

}  // namespace lancer
