// Colour-bar legends that say what they show: the map over the field's range with a title, units
// and tick labels at round numbers, drawn into a picture (right or bottom) or as a separate image.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "lancer/image/color_map.hpp"
#include "lancer/image/image.hpp"

namespace lancer {

// Where a picture's legends go (`color_by = { legend = ... }`): none, along the right edge (vertical
// bars) or along the bottom edge (horizontal bars).
enum class LegendPlacement { None, Right, Bottom };

// One colour bar: the map from low to high (a constant field, whose range is one value up to float
// rounding (rangeIsOneValue), shows the map's middle colour and one label), `bands` > 0 draws it in that many
// discrete bands as the surface shows them; on a log scale the bar is the map along log(value) and its ticks
// are decades.
struct LegendSpec {
  ColorMap map;
  double low = 0;
  double high = 1;
  std::string title;  // default: the field's name
  std::string units;  // shown after the title in parentheses
  int bands = 0;
  ColorScale scale = ColorScale::Linear;
};

// Round tick values inside [low, high]: multiples of a step 1, 2 or 5 times a power of ten, chosen
// as in Heckbert's "Nice numbers for graph labels" (Graphics Gems, 1990) for about `targetCount`
// ticks, with at least three (or half of targetCount) when low < high (one, the value, when the
// range is one value: low == high, or no wider than float rounding, rangeIsOneValue).
struct NiceTicks {
  std::vector<double> values;
  double step = 0;
};
NiceTicks niceTicks(double low, double high, int targetCount = 5);

// Ticks for a log scale over [low, high] (0 < low <= high): the powers of ten inside it (every k-th
// when more than about `targetCount`), with 2 and 5 times them added while fewer than three fit, and
// niceTicks' values when not even those give two. `step` is 0 (labels: logTickLabels).
NiceTicks logTicks(double low, double high, int targetCount = 5);
// Their labels: plain decimals ("0.01", "20", "1000") while every value is in [0.001, 100000),
// otherwise powers of ten ("10⁻³", "2×10⁻³", "10⁶").
std::vector<std::string> logTickLabels(const NiceTicks& ticks);

// The ticks' labels, all in one notation: plain decimals with the digits the step needs ("0.25",
// "1500", "−2") while every |value| is in [0.001, 100000); otherwise a mantissa and one common power
// of ten ("1.5×10⁵", "−2×10⁻⁴"). Minus signs are U+2212, zero is "0".
std::vector<std::string> tickLabels(const NiceTicks& ticks);

// "title (units)", "title", or "(units)".
std::string legendTitle(const LegendSpec& spec);

// A legend on an opaque white panel, for `--legend FILE`: vertical (bar `barLength` pixels tall,
// labels on its right) or horizontal (bar that wide, labels below), text `textHeight` pixels.
// Its size follows from the bar, the labels and the title. `linearize`: decode the map's display
// colours to linear (for pictures written with --srgb), as the surface's field colours are.
Image legendImage(const LegendSpec& spec, bool horizontal, int barLength, float textHeight, bool linearize);

// The `--legend FILE` image: every legend as a vertical bar `barLength` tall with text
// `textHeight` pixels, side by side on white.
Image legendSheet(std::span<const LegendSpec> legends, int barLength, float textHeight, bool linearize);

// Draws the legends into `picture` along the edge `placement` names, on translucent white panels,
// sized from the picture's height (vertical bars ~55% of it) or width (horizontal bars ~45%).
// Several legends sit side by side (right) or one above the other (bottom).
void drawLegends(Image& picture, std::span<const LegendSpec> legends, LegendPlacement placement,
                 bool linearize);

// How far from its edge (right or bottom, as `placement` says) drawLegends' panels reach into a
// picture `width` x `height`, with the margin beside them: the automatic camera frames the model in
// the rest, so that the legends never cover it. 0 for no legend.
int legendsBreadth(std::span<const LegendSpec> legends, LegendPlacement placement, int width, int height);

// The same legends' part that falls in `rows`, a band of a picture `width` x `height` whose first
// row is the picture's `firstRow` (a job-array task's or a rank's band items): the bands drawn
// one by one make the picture drawLegends draws in one go.
void drawLegendsInRows(Image& rows, std::span<const LegendSpec> legends, LegendPlacement placement,
                       bool linearize, int width, int height, int firstRow);

}  // namespace lancer
