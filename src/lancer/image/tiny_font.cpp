#include "lancer/image/tiny_font.hpp"

#include <cstdint>

namespace lancer {
namespace {

// One row per byte, bit 4 the leftmost column.
struct Glyph {
  char character;
  std::uint8_t rows[kTinyFontHeight];
};

constexpr Glyph kGlyphs[] = {
    {'0', {0x0E, 0x11, 0x13, 0x15, 0x19, 0x11, 0x0E}}, {'1', {0x04, 0x0C, 0x04, 0x04, 0x04, 0x04, 0x0E}},
    {'2', {0x0E, 0x11, 0x01, 0x02, 0x04, 0x08, 0x1F}}, {'3', {0x1F, 0x02, 0x04, 0x02, 0x01, 0x11, 0x0E}},
    {'4', {0x02, 0x06, 0x0A, 0x12, 0x1F, 0x02, 0x02}}, {'5', {0x1F, 0x10, 0x1E, 0x01, 0x01, 0x11, 0x0E}},
    {'6', {0x06, 0x08, 0x10, 0x1E, 0x11, 0x11, 0x0E}}, {'7', {0x1F, 0x01, 0x02, 0x04, 0x08, 0x08, 0x08}},
    {'8', {0x0E, 0x11, 0x11, 0x0E, 0x11, 0x11, 0x0E}}, {'9', {0x0E, 0x11, 0x11, 0x0F, 0x01, 0x02, 0x0C}},
    {'.', {0x00, 0x00, 0x00, 0x00, 0x00, 0x0C, 0x0C}}, {'-', {0x00, 0x00, 0x00, 0x1F, 0x00, 0x00, 0x00}},
    {'+', {0x00, 0x04, 0x04, 0x1F, 0x04, 0x04, 0x00}}, {'e', {0x00, 0x00, 0x0E, 0x11, 0x1F, 0x10, 0x0E}},
};

const Glyph* findGlyph(char c) {
  for (const Glyph& glyph : kGlyphs)
    if (glyph.character == c) return &glyph;
  return nullptr;
}

}  // namespace

int tinyTextWidth(std::string_view text, int scale) {
  if (text.empty()) return 0;
  return static_cast<int>(text.size()) * (kTinyFontWidth + 1) * scale - scale;
}

void drawTinyText(Image& image, int x, int y, std::string_view text, int scale, const Rgba& ink) {
  for (std::size_t i = 0; i < text.size(); ++i) {
    const Glyph* glyph = findGlyph(text[i]);
    if (glyph == nullptr) continue;
    const int left = x + static_cast<int>(i) * (kTinyFontWidth + 1) * scale;
    for (int row = 0; row < kTinyFontHeight; ++row) {
      for (int column = 0; column < kTinyFontWidth; ++column) {
        if (!(glyph->rows[row] & (0x10 >> column))) continue;
        for (int dy = 0; dy < scale; ++dy) {
          for (int dx = 0; dx < scale; ++dx) {
            const int px = left + column * scale + dx, py = y + row * scale + dy;
            if (px >= 0 && py >= 0 && px < image.width() && py < image.height()) image.at(px, py) = ink;
          }
        }
      }
    }
  }
}

}  // namespace lancer
