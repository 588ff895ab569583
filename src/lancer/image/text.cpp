#include "lancer/image/text.hpp"

#include <fontconfig/fontconfig.h>
#include <ft2build.h>
#include FT_FREETYPE_H

#include <strings.h>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <unordered_map>
#include <vector>

#include "lancer/util/input_error.hpp"

namespace lancer {
namespace {

constexpr std::string_view kDefaultFamily = "DejaVu Sans";
constexpr const char* kDebianDejaVuSans = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
constexpr char32_t kReplacement = 0xFFFD;

// One rasterised glyph: 8-bit coverage rows, its offset from the pen (left, and top above the
// baseline) and the pen's advance in 1/64 pixels.
struct Glyph {
  int left = 0, top = 0, width = 0, height = 0;
  long advance = 0;
  std::vector<std::uint8_t> coverage;
};

struct PlacedGlyph {
  const Glyph* glyph;
  int x, y;  // top-left of its coverage, relative to the pen origin
};

// A coverage mask over a box of the image (x0, y0 its top-left in image pixels).
struct Mask {
  int x0 = 0, y0 = 0, width = 0, height = 0;
  std::vector<float> values;

  Mask(int left, int top, int w, int h)
      : x0(left), y0(top), width(w), height(h), values(static_cast<std::size_t>(w) * h, 0.0f) {}
  float& at(int x, int y) { return values[static_cast<std::size_t>(y) * width + x]; }
  float at(int x, int y) const { return values[static_cast<std::size_t>(y) * width + x]; }
};

// The halo: at each pixel the largest coverage within `radius`, fading over the last pixel so that
// its edge is anti-aliased too.
Mask dilate(const Mask& text, float radius) {
  Mask halo(text.x0, text.y0, text.width, text.height);
  const int reach = static_cast<int>(std::ceil(radius));
  for (int y = 0; y < text.height; ++y)
    for (int x = 0; x < text.width; ++x) {
      const float c = text.at(x, y);
      if (c <= 0) continue;
      for (int dy = -reach; dy <= reach; ++dy)
        for (int dx = -reach; dx <= reach; ++dx) {
          const int hx = x + dx, hy = y + dy;
          if (hx < 0 || hy < 0 || hx >= halo.width || hy >= halo.height) continue;
          const float edge = std::clamp(
              radius + 0.5f - std::hypot(static_cast<float>(dx), static_cast<float>(dy)), 0.0f, 1.0f);
          halo.at(hx, hy) = std::max(halo.at(hx, hy), c * edge);
        }
    }
  return halo;
}

void composite(Image& image, const Mask& mask, const Vec3& colour, float opacity) {
  for (int y = 0; y < mask.height; ++y) {
    const int iy = mask.y0 + y;
    if (iy < 0 || iy >= image.height()) continue;
    for (int x = 0; x < mask.width; ++x) {
      const int ix = mask.x0 + x;
      if (ix < 0 || ix >= image.width()) continue;
      blendOver(image.at(ix, iy), colour, mask.at(x, y) * opacity);
    }
  }
}

}  // namespace

std::u32string decodeUtf8(std::string_view text) {
  std::u32string out;
  out.reserve(text.size());
  std::size_t i = 0;
  while (i < text.size()) {
    const auto lead = static_cast<unsigned char>(text[i]);
    int length = 0;
    char32_t code = 0, least = 0;
    if (lead < 0x80) {
      length = 1, code = lead;
    } else if ((lead & 0xE0) == 0xC0) {
      length = 2, code = lead & 0x1Fu, least = 0x80;
    } else if ((lead & 0xF0) == 0xE0) {
      length = 3, code = lead & 0x0Fu, least = 0x800;
    } else if ((lead & 0xF8) == 0xF0) {
      length = 4, code = lead & 0x07u, least = 0x10000;
    }
    bool valid = length > 0 && i + static_cast<std::size_t>(length) <= text.size();
    for (int k = 1; valid && k < length; ++k) {
      const auto next = static_cast<unsigned char>(text[i + static_cast<std::size_t>(k)]);
      valid = (next & 0xC0) == 0x80;
      code = (code << 6) | (next & 0x3Fu);
    }
    // Overlong forms, surrogates and code points past U+10FFFF are not UTF-8.
    valid = valid && code >= least && code <= 0x10FFFF && !(code >= 0xD800 && code <= 0xDFFF);
    out.push_back(valid ? code : kReplacement);
    i += valid ? static_cast<std::size_t>(length) : 1;
  }
  return out;
}

struct Font::Impl {
  std::string path;
  FT_Library library = nullptr;
  FT_Face face = nullptr;
  std::mutex mutex;
  // Key: the size in 1/64 pixels above, the glyph index below. Elements stay put when it grows.
  std::unordered_map<std::uint64_t, Glyph> glyphs;

  ~Impl() {
    if (face) FT_Done_Face(face);
    if (library) FT_Done_FreeType(library);
  }

  static long sizeOf(float pixelHeight) {
    return std::clamp(std::lround(static_cast<double>(pixelHeight) * 64), 64L, 1024L * 64);
  }

  const Glyph& glyph(unsigned index, long size) {
    const std::uint64_t key = (static_cast<std::uint64_t>(size) << 32) | index;
    auto found = glyphs.find(key);
    if (found != glyphs.end()) return found->second;
    Glyph g;
    // Light hinting: vertical only, so stems sit on pixel rows and the shapes stay DejaVu's.
    if (FT_Load_Glyph(face, index, FT_LOAD_RENDER | FT_LOAD_TARGET_LIGHT) == 0) {
      const FT_GlyphSlot slot = face->glyph;
      const FT_Bitmap& bitmap = slot->bitmap;
      g.left = slot->bitmap_left;
      g.top = slot->bitmap_top;
      g.advance = slot->advance.x;
      if (bitmap.pixel_mode == FT_PIXEL_MODE_GRAY) {
        g.width = static_cast<int>(bitmap.width);
        g.height = static_cast<int>(bitmap.rows);
        g.coverage.resize(static_cast<std::size_t>(g.width) * static_cast<std::size_t>(g.height));
        for (int y = 0; y < g.height; ++y)
          std::copy_n(bitmap.buffer + static_cast<std::ptrdiff_t>(y) * bitmap.pitch, g.width,
                      g.coverage.begin() + static_cast<std::ptrdiff_t>(y) * g.width);
      }
    }
    return glyphs.emplace(key, std::move(g)).first->second;
  }

  // Places the glyphs of `text` along the pen; the caller holds the mutex.
  std::vector<PlacedGlyph> layout(std::string_view text, float pixelHeight, TextMetrics& metrics) {
    const long size = sizeOf(pixelHeight);
    FT_Set_Char_Size(face, 0, size, 72, 72);  // 72 dpi: points are pixels
    metrics = {};
    metrics.ascent = static_cast<float>(face->size->metrics.ascender) / 64.0f;
    metrics.descent = static_cast<float>(-face->size->metrics.descender) / 64.0f;
    std::vector<PlacedGlyph> placed;
    long pen = 0;
    unsigned previous = 0;
    bool inked = false;
    for (const char32_t code : decodeUtf8(text)) {
      const unsigned index = FT_Get_Char_Index(face, code);
      if (previous != 0 && index != 0 && FT_HAS_KERNING(face)) {
        FT_Vector kerning{};
        if (FT_Get_Kerning(face, previous, index, FT_KERNING_DEFAULT, &kerning) == 0) pen += kerning.x;
      }
      const Glyph& g = glyph(index, size);
      const int x = static_cast<int>((pen + 32) >> 6) + g.left, y = -g.top;
      if (g.width > 0 && g.height > 0) {
        placed.push_back({&g, x, y});
        metrics.inkLeft = inked ? std::min(metrics.inkLeft, x) : x;
        metrics.inkTop = inked ? std::min(metrics.inkTop, y) : y;
        metrics.inkRight = inked ? std::max(metrics.inkRight, x + g.width) : x + g.width;
        metrics.inkBottom = inked ? std::max(metrics.inkBottom, y + g.height) : y + g.height;
        inked = true;
      }
      pen += g.advance;
      previous = index;
    }
    metrics.advance = static_cast<float>(pen) / 64.0f;
    return placed;
  }
};

Font::Font(const std::string& path) : impl_(std::make_unique<Impl>()) {
  impl_->path = path;
  if (FT_Init_FreeType(&impl_->library) != 0)
    throw InputError(SourceLocation{path}, "FreeType could not start, so no text can be drawn");
  if (std::filesystem::is_directory(path))
    throw InputError(SourceLocation{path}, "this is a folder, not a font file");
  if (!std::filesystem::is_regular_file(path))
    throw InputError(SourceLocation{path}, "the font file does not exist");
  if (FT_New_Face(impl_->library, path.c_str(), 0, &impl_->face) != 0)
    throw InputError(SourceLocation{path}, "FreeType cannot read this file as a font (TrueType or OpenType)");
  if (!FT_IS_SCALABLE(impl_->face))
    throw InputError(SourceLocation{path}, "the font is a bitmap font; lancer needs a scalable one");
}

Font::~Font() = default;
Font::Font(Font&&) noexcept = default;
Font& Font::operator=(Font&&) noexcept = default;

const std::string& Font::path() const { return impl_->path; }

TextMetrics Font::measure(std::string_view text, float pixelHeight) const {
  const std::lock_guard lock(impl_->mutex);
  TextMetrics metrics;
  impl_->layout(text, pixelHeight, metrics);
  return metrics;
}

void Font::draw(Image& image, int x, int baselineY, std::string_view text, float pixelHeight,
                const TextStyle& style) const {
  const std::lock_guard lock(impl_->mutex);
  TextMetrics metrics;
  const std::vector<PlacedGlyph> placed = impl_->layout(text, pixelHeight, metrics);
  if (placed.empty()) return;
  const int margin = style.halo ? static_cast<int>(std::ceil(style.haloRadius)) : 0;
  Mask mask(x + metrics.inkLeft - margin, baselineY + metrics.inkTop - margin,
            metrics.inkWidth() + 2 * margin, metrics.inkHeight() + 2 * margin);
  for (const PlacedGlyph& p : placed) {
    const int left = x + p.x - mask.x0, top = baselineY + p.y - mask.y0;
    for (int gy = 0; gy < p.glyph->height; ++gy)
      for (int gx = 0; gx < p.glyph->width; ++gx) {
        const float c = p.glyph->coverage[static_cast<std::size_t>(gy) * p.glyph->width + gx] / 255.0f;
        float& m = mask.at(left + gx, top + gy);
        m = std::max(m, c);  // overlapping glyphs (kerned pairs) do not ink twice
      }
  }
  if (style.halo) composite(image, dilate(mask, style.haloRadius), *style.halo, style.opacity);
  composite(image, mask, style.colour, style.opacity);
}

std::string findFontFile(std::string_view family, const std::string& fallbackPath) {
  std::string found;
  if (FcConfig* config = FcInitLoadConfigAndFonts()) {
    const std::string name(family);
    FcPattern* pattern = FcNameParse(reinterpret_cast<const FcChar8*>(name.c_str()));
    if (pattern) {
      FcConfigSubstitute(config, pattern, FcMatchPattern);
      FcDefaultSubstitute(pattern);
      FcResult result = FcResultNoMatch;
      if (FcPattern* match = FcFontMatch(config, pattern, &result)) {
        // fontconfig always answers with some font: keep it only when it is the family asked for.
        FcChar8* file = nullptr;
        FcChar8* matchedFamily = nullptr;
        if (FcPatternGetString(match, FC_FILE, 0, &file) == FcResultMatch &&
            FcPatternGetString(match, FC_FAMILY, 0, &matchedFamily) == FcResultMatch &&
            strcasecmp(reinterpret_cast<const char*>(matchedFamily), name.c_str()) == 0)
          found = reinterpret_cast<const char*>(file);
        FcPatternDestroy(match);
      }
      FcPatternDestroy(pattern);
    }
    FcConfigDestroy(config);
  }
  if (!found.empty() && std::filesystem::is_regular_file(found)) return found;
  if (std::filesystem::is_regular_file(fallbackPath)) return fallbackPath;
  throw InputError(SourceLocation{fallbackPath},
                   "lancer draws text with the font " + std::string(family) +
                       ", which fontconfig does not know and which is not at this path: install it "
                       "(Debian: apt-get install fonts-dejavu-core fontconfig) or set LANCER_FONT to a "
                       "TrueType font file");
}

const Font& defaultFont() {
  static std::mutex mutex;
  static std::unique_ptr<Font> font;
  const std::lock_guard lock(mutex);
  if (!font) {
    const char* chosen = std::getenv("LANCER_FONT");  // NOLINT(concurrency-mt-unsafe): read under the lock
    font = std::make_unique<Font>(chosen && *chosen ? std::string(chosen)
                                                    : findFontFile(kDefaultFamily, kDebianDejaVuSans));
  }
  return *font;
}

}  // namespace lancer
