// A 5x7 pixel font for the few characters numbers need ("0-9 . - + e"), so that lancer can label a
// colour-bar legend without a font library.
#pragma once

#include <string_view>

#include "lancer/image/image.hpp"

namespace lancer {

inline constexpr int kTinyFontWidth = 5;
inline constexpr int kTinyFontHeight = 7;

// Width in pixels of `text` at `scale` (one blank column between characters).
int tinyTextWidth(std::string_view text, int scale);

// Draws `text` with its top-left corner at (x, y), each font pixel a scale x scale block of `ink`;
// characters the font lacks are drawn as blanks; pixels outside the image are skipped.
void drawTinyText(Image& image, int x, int y, std::string_view text, int scale, const Rgba& ink);

}  // namespace lancer
