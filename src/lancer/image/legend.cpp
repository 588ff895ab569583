#include "lancer/image/legend.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "lancer/image/pixel_encoding.hpp"
#include "lancer/image/text.hpp"

namespace lancer {
namespace {

constexpr Vec3 kInk{0, 0, 0};
constexpr Vec3 kTickInk{0.1f, 0.1f, 0.1f};
constexpr Vec3 kPaper{1, 1, 1};
constexpr float kPanelOpacity = 0.85f;  // in pictures: the surface shows faintly behind the legend

// Heckbert's nice number: 1, 2, 5 or 10 times a power of ten near x (rounded, or at least x).
double niceNumber(double x, bool round) {
  const double power = std::pow(10.0, std::floor(std::log10(x)));
  const double f = x / power;
  double nice = 10;
  if (round)
    nice = f < 1.5 ? 1 : f < 3 ? 2 : f < 7 ? 5 : 10;
  else
    nice = f <= 1 ? 1 : f <= 2 ? 2 : f <= 5 ? 5 : 10;
  return nice * power;
}

// The next smaller nice step: 10 -> 5 -> 2 -> 1 -> 0.5 ...
double smallerStep(double step) {
  const double power = std::pow(10.0, std::floor(std::log10(step) + 1e-9));
  const double f = step / power;
  return f > 4 ? 2 * power : f > 1.5 ? power : 0.5 * power;
}

std::string superscript(int exponent) {
  static constexpr const char* kDigits[] = {"\u2070", "\u00b9", "\u00b2", "\u00b3", "\u2074",
                                            "\u2075", "\u2076", "\u2077", "\u2078", "\u2079"};
  std::string text = exponent < 0 ? "\u207b" : "";
  for (const char digit : std::to_string(std::abs(exponent))) text += kDigits[digit - '0'];
  return text;
}

// "-1.50" with a real minus sign.
std::string withMinus(std::string text) {
  if (!text.empty() && text[0] == '-') text.replace(0, 1, "\u2212");
  return text;
}

struct Layout {
  const Font& font;
  float textHeight;
  int pad, barThickness, tickLength, labelGap, digitHeight, titleBlock;
};

Layout layoutFor(float textHeight, bool hasTitle) {
  const Font& font = defaultFont();
  const TextMetrics line = font.measure("0", textHeight);
  return {font,
          textHeight,
          std::max(3, static_cast<int>(std::lround(0.6f * textHeight))),
          std::max(6, static_cast<int>(std::lround(1.2f * textHeight))),
          std::max(3, static_cast<int>(std::lround(0.35f * textHeight))),
          std::max(2, static_cast<int>(std::lround(0.3f * textHeight))),
          line.inkHeight(),
          hasTitle ? static_cast<int>(std::ceil(line.ascent + line.descent)) : 0};
}

Vec3 barColour(const LegendSpec& spec, float t, bool linearize) {
  if (rangeIsOneValue(spec.low, spec.high)) t = 0.5f;  // a constant field shows the map's middle colour
  if (spec.bands > 0)
    t = (std::min(std::floor(t * static_cast<float>(spec.bands)), static_cast<float>(spec.bands - 1)) +
         0.5f) /
        static_cast<float>(spec.bands);
  Vec3 c = spec.map(t);
  if (linearize) c = {linearFromSrgb(c.x), linearFromSrgb(c.y), linearFromSrgb(c.z)};
  return c;
}

bool onLogScale(const LegendSpec& spec) {
  return spec.scale == ColorScale::Log && spec.low > 0 && !rangeIsOneValue(spec.low, spec.high) &&
         std::isfinite(spec.high);
}

Image legendPanel(const LegendSpec& spec, bool horizontal, int barLength, float textHeight, bool linearize,
                  float panelOpacity) {
  barLength = std::max(barLength, 16);
  const std::string title = legendTitle(spec);
  const Layout l = layoutFor(textHeight, !title.empty());
  const int tickCount = horizontal ? 4 : 6;
  const bool log = onLogScale(spec);
  const NiceTicks ticks =
      log ? logTicks(spec.low, spec.high, tickCount) : niceTicks(spec.low, spec.high, tickCount);
  const std::vector<std::string> labels = log ? logTickLabels(ticks) : tickLabels(ticks);
  const MapPosition tickFraction(spec.low, spec.high, log ? ColorScale::Log : ColorScale::Linear);
  std::vector<TextMetrics> labelMetrics;
  int widestLabel = 0;
  for (const std::string& label : labels) {
    labelMetrics.push_back(l.font.measure(label, textHeight));
    widestLabel = std::max(widestLabel, static_cast<int>(std::ceil(labelMetrics.back().advance)));
  }
  const int titleWidth =
      title.empty() ? 0 : static_cast<int>(std::ceil(l.font.measure(title, textHeight).advance));
  const int titleSpace = title.empty() ? 0 : l.titleBlock + l.pad / 2;

  int width = 0, height = 0, barX = 0, barY = 0;
  if (horizontal) {
    barX = l.pad + widestLabel / 2;
    barY = l.pad + titleSpace;
    width = std::max(barX + barLength + widestLabel / 2 + l.pad, titleWidth + 2 * l.pad);
    height = barY + l.barThickness + l.tickLength + l.labelGap + l.digitHeight + l.pad;
  } else {
    barX = l.pad;
    barY = l.pad + titleSpace + l.digitHeight / 2 + 1;
    width = std::max(barX + l.barThickness + l.tickLength + l.labelGap + widestLabel + l.pad,
                     titleWidth + 2 * l.pad);
    height = barY + barLength + l.digitHeight / 2 + 1 + l.pad;
  }
  Image panel(width, height, toRgba(kPaper, panelOpacity));
  if (!title.empty())
    l.font.draw(panel, l.pad, l.pad + static_cast<int>(std::lround(l.titleBlock * 0.78f)), title, textHeight,
                TextStyle(kInk));
  // The bar: pixel centres sample the map, low at the bottom (vertical) or the left (horizontal).
  const int along = barLength, across = l.barThickness;
  for (int i = 0; i < along; ++i) {
    const float t = (static_cast<float>(i) + 0.5f) / static_cast<float>(along);
    const Vec3 c = barColour(spec, t, linearize);
    for (int j = 0; j < across; ++j) {
      if (horizontal)
        panel.at(barX + i, barY + j) = toRgba(c);
      else
        panel.at(barX + j, barY + along - 1 - i) = toRgba(c);
    }
  }
  for (std::size_t k = 0; k < ticks.values.size(); ++k) {
    const float f = tickFraction(ticks.values[k]);
    const int offset = static_cast<int>(std::lround(f * static_cast<float>(along - 1)));
    const TextMetrics& m = labelMetrics[k];
    if (horizontal) {
      const int x = barX + offset;
      for (int y = barY + across; y < barY + across + l.tickLength; ++y) panel.at(x, y) = toRgba(kTickInk);
      l.font.draw(panel, x - static_cast<int>(std::lround(m.advance / 2)),
                  barY + across + l.tickLength + l.labelGap + l.digitHeight, labels[k], textHeight,
                  TextStyle(kInk));
    } else {
      const int y = barY + along - 1 - offset;
      for (int x = barX + across; x < barX + across + l.tickLength; ++x) panel.at(x, y) = toRgba(kTickInk);
      l.font.draw(panel, barX + across + l.tickLength + l.labelGap, y + l.digitHeight / 2, labels[k],
                  textHeight, TextStyle(kInk));
    }
  }
  return panel;
}

}  // namespace

NiceTicks niceTicks(double low, double high, int targetCount) {
  NiceTicks ticks;
  if (!std::isfinite(low) || !std::isfinite(high)) {
    ticks.values = {low};
    return ticks;
  }
  if (rangeIsOneValue(low, high)) {  // a constant field, up to float rounding: its one value
    ticks.values = {low + (high - low) / 2};
    return ticks;
  }
  targetCount = std::max(targetCount, 2);
  // Heckbert: a nice step for the range split into targetCount - 1 parts, then the multiples of it
  // that lie in [low, high] (the bar spans exactly the range, so ticks outside it are dropped).
  // Heckbert's loose labelling would widen the range to the outer ticks; here a range such as
  // 0..240 would keep only 0 and 200, so the step shrinks until three (or half the wanted) are there.
  double step = niceNumber(niceNumber(high - low, false) / (targetCount - 1), true);
  const double slack = 1e-9 * (high - low);
  const std::size_t fewest = static_cast<std::size_t>(std::max(3, targetCount / 2));
  for (;;) {
    ticks.values.clear();
    const double first = std::ceil((low - slack) / step);
    for (double k = first; k * step <= high + slack; k += 1)
      ticks.values.push_back(k * step == 0 ? 0.0 : k * step);
    if (ticks.values.size() >= fewest) break;
    step = smallerStep(step);
  }
  ticks.step = step;
  return ticks;
}

NiceTicks logTicks(double low, double high, int targetCount) {
  if (!(low > 0) || rangeIsOneValue(low, high) || !std::isfinite(high))
    return niceTicks(low, high, targetCount);
  targetCount = std::max(targetCount, 2);
  constexpr double kSlack = 1e-9;
  const int first = static_cast<int>(std::ceil(std::log10(low) - kSlack));
  const int last = static_cast<int>(std::floor(std::log10(high) + kSlack));
  NiceTicks ticks;
  const int decades = last - first + 1;
  if (decades >= 3) {
    // Every k-th power of ten, k such that about targetCount remain, aligned so that 10^0 is one.
    const int every = (decades + targetCount - 1) / targetCount;
    for (int e = first; e <= last; ++e)
      if (((e % every) + every) % every == 0) ticks.values.push_back(std::pow(10.0, e));
    if (ticks.values.size() >= 2) return ticks;
    ticks.values.clear();
    for (int e = first; e <= last; e += every) ticks.values.push_back(std::pow(10.0, e));
    return ticks;
  }
  // A short range: 1, then 1 and 5, then 1, 2 and 5 times the powers of ten, the first that gives three.
  constexpr std::array<std::array<double, 3>, 3> kMultiples = {{{1, 0, 0}, {1, 5, 0}, {1, 2, 5}}};
  for (const auto& multiples : kMultiples) {
    ticks.values.clear();
    for (int e = first - 1; e <= last; ++e)
      for (const double m : multiples) {
        const double value = m * std::pow(10.0, e);
        if (m > 0 && value >= low * (1 - kSlack) && value <= high * (1 + kSlack))
          ticks.values.push_back(value);
      }
    if (ticks.values.size() >= 3) break;
  }
  if (ticks.values.size() < 2) return niceTicks(low, high, targetCount);  // within one 1-2-5 step
  return ticks;
}

std::vector<std::string> logTickLabels(const NiceTicks& ticks) {
  if (ticks.step > 0) return tickLabels(ticks);  // niceTicks' values, for a range within a 1-2-5 step
  const bool plain = std::all_of(ticks.values.begin(), ticks.values.end(),
                                 [](double v) { return v >= 1e-3 * (1 - 1e-9) && v < 1e5; });
  std::vector<std::string> labels;
  for (const double v : ticks.values) {
    if (plain) {
      labels.push_back(fmt::format("{:g}", v));
      continue;
    }
    const int exponent = static_cast<int>(std::floor(std::log10(v) + 1e-9));
    const long mantissa = std::lround(v / std::pow(10.0, exponent));
    labels.push_back((mantissa == 1 ? "10" : fmt::format("{}\u00d710", mantissa)) + superscript(exponent));
  }
  return labels;
}

std::vector<std::string> tickLabels(const NiceTicks& ticks) {
  std::vector<std::string> labels;
  double largest = 0;
  for (const double v : ticks.values) largest = std::max(largest, std::abs(v));
  if (ticks.step <= 0) {  // one value: a constant field
    for (const double v : ticks.values) labels.push_back(withMinus(fmt::format("{:.4g}", v)));
    return labels;
  }
  const bool scientific = largest >= 1e5 || largest < 1e-3;
  const int exponent = scientific ? static_cast<int>(std::floor(std::log10(largest))) : 0;
  const double scale = std::pow(10.0, exponent);
  const int decimals = std::max(0, -static_cast<int>(std::floor(std::log10(ticks.step / scale) + 1e-9)));
  for (const double v : ticks.values) {
    if (std::abs(v) < ticks.step * 1e-6) {
      labels.emplace_back("0");
      continue;
    }
    std::string text = withMinus(fmt::format("{:.{}f}", v / scale, decimals));
    if (scientific) text += "\u00d710" + superscript(exponent);
    labels.push_back(std::move(text));
  }
  return labels;
}

std::string legendTitle(const LegendSpec& spec) {
  if (spec.units.empty()) return spec.title;
  return spec.title.empty() ? "(" + spec.units + ")" : spec.title + " (" + spec.units + ")";
}

Image legendImage(const LegendSpec& spec, bool horizontal, int barLength, float textHeight, bool linearize) {
  return legendPanel(spec, horizontal, barLength, textHeight, linearize, 1.0f);
}

Image legendSheet(std::span<const LegendSpec> legends, int barLength, float textHeight, bool linearize) {
  std::vector<Image> panels;
  int width = 0, height = 0;
  for (const LegendSpec& spec : legends) {
    panels.push_back(legendImage(spec, false, barLength, textHeight, linearize));
    width += panels.back().width();
    height = std::max(height, panels.back().height());
  }
  Image sheet(std::max(width, 1), std::max(height, 1), toRgba(kPaper));
  int x = 0;
  for (const Image& panel : panels) {
    sheet.pasteTile(panel, x, 0);
    x += panel.width();
  }
  return sheet;
}

void drawLegends(Image& picture, std::span<const LegendSpec> legends, LegendPlacement placement,
                 bool linearize) {
  drawLegendsInRows(picture, legends, placement, linearize, picture.width(), picture.height(), 0);
}

namespace {

// The legends' panels and where their top-left corners go in a picture `width` x `height`: along the
// edge `placement` names, side by side (right) or one above the other (bottom), a margin apart.
struct PlacedPanel {
  Image panel;
  int x0 = 0, y0 = 0;
};
struct LegendLayout {
  std::vector<PlacedPanel> panels;
  int margin = 0;
};
LegendLayout layOutLegends(std::span<const LegendSpec> legends, LegendPlacement placement, bool linearize,
                           int width, int height) {
  LegendLayout layout;
  if (placement == LegendPlacement::None || legends.empty()) return layout;
  const bool horizontal = placement == LegendPlacement::Bottom;
  const float textHeight = std::max(9.0f, static_cast<float>(height) / 40.0f);
  layout.margin = static_cast<int>(std::lround(0.6f * textHeight));
  const int barLength =
      horizontal ? static_cast<int>(std::lround(0.45 * width)) : static_cast<int>(std::lround(0.55 * height));
  int right = width - layout.margin, bottom = height - layout.margin;
  for (const LegendSpec& spec : legends) {
    PlacedPanel placed;
    placed.panel = legendPanel(spec, horizontal, barLength, textHeight, linearize, kPanelOpacity);
    placed.x0 = horizontal ? (width - placed.panel.width()) / 2 : right - placed.panel.width();
    placed.y0 = horizontal ? bottom - placed.panel.height() : (height - placed.panel.height()) / 2;
    if (horizontal)
      bottom = placed.y0 - layout.margin;
    else
      right = placed.x0 - layout.margin;
    layout.panels.push_back(std::move(placed));
  }
  return layout;
}

}  // namespace

int legendsBreadth(std::span<const LegendSpec> legends, LegendPlacement placement, int width, int height) {
  const LegendLayout layout = layOutLegends(legends, placement, false, width, height);
  if (layout.panels.empty()) return 0;
  const PlacedPanel& inner = layout.panels.back();
  const int edge = placement == LegendPlacement::Bottom ? height - inner.y0 : width - inner.x0;
  return edge + layout.margin;
}

void drawLegendsInRows(Image& rows, std::span<const LegendSpec> legends, LegendPlacement placement,
                       bool linearize, int width, int height, int firstRow) {
  if (rows.empty()) return;
  for (const PlacedPanel& placed : layOutLegends(legends, placement, linearize, width, height).panels) {
    const Image& panel = placed.panel;
    const int x0 = placed.x0, y0 = placed.y0;
    // The panel's rows that fall in this band of the picture.
    const int yBegin = std::max(0, firstRow - y0),
              yEnd = std::min(panel.height(), firstRow + rows.height() - y0);
    for (int y = yBegin; y < yEnd; ++y)
      for (int x = 0; x < panel.width(); ++x) {
        const int px = x0 + x, py = y0 + y;
        if (px < 0 || py < 0 || px >= rows.width() || py >= height) continue;
        const Rgba& p = panel.at(x, y);
        blendOver(rows.at(px, py - firstRow), p.rgb(), p.a);
      }
  }
}

}  // namespace lancer
