// Text drawn with FreeType and DejaVu Sans: a glyph's coverage, measured against drawn ink boxes,
// halos, blending over transparent pixels, UTF-8 decoding and the errors for a missing font.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "lancer/image/text.hpp"
#include "lancer/util/input_error.hpp"
#include "support/input_errors.hpp"

namespace lancer {
namespace {

// The box of pixels with any alpha: x0, y0, x1, y1 (exclusive); all zero when there is none.
struct Box {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  friend bool operator==(const Box&, const Box&) = default;
};

Box alphaBox(const Image& image) {
  Box box{image.width(), image.height(), 0, 0};
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x)
      if (image.at(x, y).a > 0) {
        box.x0 = std::min(box.x0, x), box.y0 = std::min(box.y0, y);
        box.x1 = std::max(box.x1, x + 1), box.y1 = std::max(box.y1, y + 1);
      }
  return box.x1 == 0 ? Box{} : box;
}

void PrintTo(const Box& b, std::ostream* os) { *os << b.x0 << "," << b.y0 << " .. " << b.x1 << "," << b.y1; }

TEST(Text, FullBlockGlyphCoversItsBoxSolidly) {
  // U+2588 FULL BLOCK is a rectangle: every pixel inside its ink box is fully covered, only the rim
  // may be partial, and it spans the font's descent to its ascent.
  const Font& font = defaultFont();
  const TextMetrics m = font.measure("\u2588", 32);
  Image image(80, 80, {0, 0, 0, 0});
  font.draw(image, 20, 50, "\u2588", 32);
  double sum = 0;
  for (const Rgba& p : image.pixels()) sum += p.a;
  const int w = m.inkWidth(), h = m.inkHeight();
  EXPECT_GE(sum, (w - 2) * (h - 2));
  EXPECT_LE(sum, w * h);
  for (int y = 50 + m.inkTop + 1; y < 50 + m.inkBottom - 1; ++y)
    for (int x = 20 + m.inkLeft + 1; x < 20 + m.inkRight - 1; ++x)
      EXPECT_EQ(image.at(x, y).a, 1.0f) << x << "," << y;
  EXPECT_NEAR(h, m.ascent + m.descent, 2.0);
}

TEST(Text, CurvesAreAntiAliased) {
  Image image(60, 60, {1, 1, 1, 1});
  defaultFont().draw(image, 10, 45, "O", 40);
  int partial = 0, solid = 0;
  for (const Rgba& p : image.pixels()) {
    partial += p.r > 0.05f && p.r < 0.95f ? 1 : 0;
    solid += p.r == 0 ? 1 : 0;
  }
  EXPECT_GT(partial, 20);
  EXPECT_GT(solid, 50);
}

TEST(Text, MeasuredInkBoxIsTheDrawnOne) {
  const Font& font = defaultFont();
  for (const char* text : {"0.25", "-1.5\u00d710\u2075", "von Mises stress (MPa)", "gjpqy", "T"})
    for (float size : {9.0f, 13.0f, 24.5f}) {
      const TextMetrics m = font.measure(text, size);
      Image image(400, 80, {0, 0, 0, 0});
      font.draw(image, 30, 50, text, size);
      EXPECT_EQ(alphaBox(image), (Box{30 + m.inkLeft, 50 + m.inkTop, 30 + m.inkRight, 50 + m.inkBottom}))
          << text << " at " << size;
      EXPECT_GE(m.advance, static_cast<float>(m.inkRight) - 1.0f) << text;
      EXPECT_GT(m.ascent, 0.7f * size);
      EXPECT_GT(m.descent, 0.1f * size);
    }
}

TEST(Text, AdvanceScalesWithSizeAndTextLength) {
  const Font& font = defaultFont();
  const float ten = font.measure("0123456789", 10).advance, forty = font.measure("0123456789", 40).advance;
  // DejaVu Sans's digits are 0.636 em wide; hinting rounds each advance to whole pixels.
  EXPECT_NEAR(ten, 63.6f, 10.0f);
  EXPECT_NEAR(forty, 254.4f, 10.0f);
  EXPECT_EQ(font.measure("", 20).advance, 0.0f);
  EXPECT_EQ(font.measure("", 20).inkWidth(), 0);
  EXPECT_EQ(font.measure(" ", 20).inkWidth(), 0);
  EXPECT_GT(font.measure(" ", 20).advance, 3.0f);
}

TEST(Text, HaloSurroundsTheGlyphsByItsRadius) {
  const Font& font = defaultFont();
  const TextMetrics m = font.measure("42", 20);
  Image image(100, 60, {0, 0, 0, 0});
  TextStyle style({1, 1, 1});
  style.halo = Vec3{0, 0, 0};
  style.haloRadius = 2.0f;
  font.draw(image, 30, 40, "42", 20, style);
  EXPECT_EQ(alphaBox(image),
            (Box{30 + m.inkLeft - 2, 40 + m.inkTop - 2, 30 + m.inkRight + 2, 40 + m.inkBottom + 2}));
  // Inside a stroke the text's colour, around it the halo's.
  int white = 0, black = 0;
  for (const Rgba& p : image.pixels()) {
    white += p.a == 1 && p.r == 1 ? 1 : 0;
    black += p.a == 1 && p.r == 0 ? 1 : 0;
  }
  EXPECT_GT(white, 20);
  EXPECT_GT(black, 20);
}

TEST(Text, CoverageBlendsOverWhatIsThere) {
  Image image(40, 40, {0.2f, 0.4f, 0.6f, 0});
  defaultFont().draw(image, 5, 30, "\u2588", 20, TextStyle({1, 0, 0}, 0.5f));
  // Inside the block: half-opaque red over a transparent pixel is red with alpha 0.5.
  const Rgba inside = image.at(10, 25);
  EXPECT_EQ(inside.a, 0.5f);
  EXPECT_EQ(inside.r, 1.0f);
  EXPECT_EQ(inside.g, 0.0f);
  Image opaque(40, 40, {0, 0, 1, 1});
  defaultFont().draw(opaque, 5, 30, "\u2588", 20, TextStyle({1, 0, 0}, 0.5f));
  EXPECT_EQ(opaque.at(10, 25), (Rgba{0.5f, 0, 0.5f, 1}));
  EXPECT_EQ(opaque.at(39, 0), (Rgba{0, 0, 1, 1}));  // untouched outside
}

TEST(Text, ClipsAtTheImageEdges) {
  Image image(10, 10, {1, 1, 1, 1});
  defaultFont().draw(image, -5, 8, "Wide text past both edges", 20);
  defaultFont().draw(image, 5, 200, "below", 20);
  int dark = 0;
  for (const Rgba& p : image.pixels()) dark += p.r < 0.5f ? 1 : 0;
  EXPECT_GT(dark, 5);
}

TEST(Text, DecodesUtf8AndReplacesInvalidBytes) {
  EXPECT_EQ(decodeUtf8("1\u00d710\u2075"), (std::u32string{U'1', 0xD7, U'1', U'0', 0x2075}));
  EXPECT_EQ(decodeUtf8("\xe2\x82"), (std::u32string{0xFFFD, 0xFFFD}));  // truncated
  EXPECT_EQ(decodeUtf8("a\xff"), (std::u32string{U'a', 0xFFFD}));
  EXPECT_EQ(decodeUtf8("\xc0\xaf"), (std::u32string{0xFFFD, 0xFFFD}));  // overlong '/'
  EXPECT_EQ(decodeUtf8("\xed\xa0\x80").size(), 3u);                     // a surrogate is not UTF-8
  EXPECT_EQ(decodeUtf8("\xf0\x9f\x98\x80"), (std::u32string{0x1F600}));
  Image image(40, 30, {1, 1, 1, 1});
  defaultFont().draw(image, 2, 20, "\xff\xfe", 14);  // draws replacement glyphs, no crash
}

TEST(Text, MissingFontSaysWhatToInstall) {
  EXPECT_THROW(Font("/nonexistent/lancer/DejaVuSans.ttf"), InputError);
  EXPECT_EQ(test::messageOf([] { Font font("/nonexistent/lancer/DejaVuSans.ttf"); }),
            "/nonexistent/lancer/DejaVuSans.ttf: error: the font file does not exist");
  EXPECT_EQ(test::messageOf([] { Font font(LANCER_TEST_DATA_DIR); }),
            std::string(LANCER_TEST_DATA_DIR) + ": error: this is a folder, not a font file");
  const std::string notAFont = std::string(LANCER_TEST_DATA_DIR) + "/render/field_square.toml";
  EXPECT_NE(test::messageOf([&] { Font font(notAFont); }).find("cannot read this file as a font"),
            std::string::npos);
  const std::string missing =
      test::messageOf([] { findFontFile("No Such Family Lancer", "/nonexistent/font.ttf"); });
  EXPECT_NE(
      missing.find("/nonexistent/font.ttf: error: lancer draws text with the font No Such Family Lancer"),
      std::string::npos)
      << missing;
  EXPECT_NE(missing.find("apt-get install fonts-dejavu-core"), std::string::npos) << missing;
  EXPECT_NE(missing.find("LANCER_FONT"), std::string::npos) << missing;
  // The fallback path is used when fontconfig does not know the family.
  EXPECT_EQ(findFontFile("No Such Family Lancer", defaultFont().path()), defaultFont().path());
}

}  // namespace
}  // namespace lancer
