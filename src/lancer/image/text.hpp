// Anti-aliased text drawn into an Image with a real font: FreeType rasterises DejaVu Sans (found at
// run time with fontconfig or at Debian's path) for legends, their titles and animation labels.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "lancer/image/image.hpp"
#include "lancer/math/vec3.hpp"

namespace lancer {

// Where a run of text puts its pixels, relative to its pen origin (x to the right, y down, the
// origin on the baseline where the text starts). Pixel sizes; ink bounds are exclusive on the right
// and bottom and empty (inkLeft == inkRight) for blank text.
struct TextMetrics {
  float advance = 0;  // pen advance: where text drawn next would start
  float ascent = 0;   // the font's ascent above the baseline at this size (a line's top)
  float descent = 0;  // the font's descent below the baseline, positive
  int inkLeft = 0, inkTop = 0, inkRight = 0, inkBottom = 0;

  int inkWidth() const { return inkRight - inkLeft; }
  int inkHeight() const { return inkBottom - inkTop; }
};

// How text is drawn: its colour (linear RGB, like the Image) over what is there, and an optional
// halo, a soft band of `haloRadius` pixels around every glyph in `halo`'s colour that keeps the text
// legible over a picture (the ink box grows by ceil(haloRadius) on every side).
struct TextStyle {
  TextStyle() = default;
  explicit TextStyle(const Vec3& c, float alpha = 1) : colour(c), opacity(alpha) {}

  Vec3 colour{0, 0, 0};
  float opacity = 1;
  std::optional<Vec3> halo;
  float haloRadius = 1.5f;
};

// A TrueType/OpenType font, loaded once; glyphs are rasterised once per size and cached. Text is
// UTF-8 (invalid bytes draw as U+FFFD); pixelHeight is the em size in pixels (DejaVu Sans's capitals
// are about 0.73 of it). Glyphs are placed at whole pixels along a pen that advances in 1/64 pixels,
// with the font's kerning. measure and draw may be called from several threads at once.
class Font {
 public:
  // Reads the font file at `path`; InputError naming the file when it is missing or not a font.
  explicit Font(const std::string& path);
  ~Font();
  Font(Font&&) noexcept;
  Font& operator=(Font&&) noexcept;

  TextMetrics measure(std::string_view text, float pixelHeight) const;
  // Draws `text` with its pen origin at (x, baselineY); pixels outside the image are skipped.
  // Coverage blends the style's colour over each pixel ("over" in the pixel's alpha: text on a
  // transparent image leaves the text's coverage as alpha).
  void draw(Image& image, int x, int baselineY, std::string_view text, float pixelHeight,
            const TextStyle& style = {}) const;

  const std::string& path() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The font lancer draws its text with: DejaVu Sans, from the LANCER_FONT environment variable when
// set (a font file), else fontconfig's match for "DejaVu Sans", else Debian's
// /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf. Loaded on first use and kept; InputError saying
// what to install when none is found.
const Font& defaultFont();

// The file defaultFont() would load, found as it describes; `family` and `fallbackPath` are
// parameters so that tests can ask for a font that is not there. InputError when none is found.
std::string findFontFile(std::string_view family, const std::string& fallbackPath);

// The code points of UTF-8 text; invalid or truncated sequences become U+FFFD.
std::u32string decodeUtf8(std::string_view text);

}  // namespace lancer
