// PNG through libpng. libpng reports errors by longjmp, so the functions that call it hold only
// trivially destructible locals between setjmp and the last libpng call; the C++ side (exceptions,
// vectors) stays in the callers.
#include <fmt/format.h>
#include <png.h>

#include <cerrno>
#include <csetjmp>
#include <cstring>
#include <memory>

#include "lancer/image/atomic_file.hpp"
#include "lancer/image/image_io.hpp"
#include "lancer/image/png_row_encoder.hpp"
#include "lancer/util/input_error.hpp"

namespace lancer {
namespace {

// readPng refuses more pixels than this: a tiny PNG can claim 65535x65535, 64 GiB as float RGBA.
constexpr std::uint64_t kMaxReadPixels = std::uint64_t{1} << 26;

struct PngErrorText {
  char text[kPngErrorTextSize] = {};
};

// Our own handlers: libpng's defaults print to stderr, and the library never prints. The error
// pointer is a buffer of kPngErrorTextSize characters.
void onPngError(png_structp png, png_const_charp message) {
  auto* text = static_cast<char*>(png_get_error_ptr(png));
  if (text != nullptr && message != nullptr) {
    std::strncpy(text, message, kPngErrorTextSize - 1);
  }
  png_longjmp(png, 1);
}
void onPngWarning(png_structp, png_const_charp) {}

void onPngWrite(png_structp png, png_bytep data, png_size_t size) {
  auto* file = static_cast<AtomicFileWriter*>(png_get_io_ptr(png));
  if (!file->write(data, size)) png_error(png, "write failed");
}
void onPngFlush(png_structp) {}

// tEXt holds Latin-1; a command line with other bytes (UTF-8 file names) goes into iTXt, which holds UTF-8.
bool isAscii(const std::string& text) {
  for (const char c : text)
    if (static_cast<unsigned char>(c) >= 0x80) return false;
  return true;
}

// The header chunks, shared by the whole-image and the row-by-row writers so both give the same bytes:
// IHDR, the sRGB chunks, pHYs (the DPI as pixels per metre, PNG 1.2 section 4.2.4.3) and the text
// chunks "Software" and "Comment" (the command; section 4.2.3.1 lists both keywords). Called between
// setjmp and the last libpng call: `texts` points into `metadata`'s strings.
void writePngHeader(png_structp png, png_infop info, int width, int height, int channels, bool srgbChunk,
                    int bitDepth, const ImageMetadata& metadata) {
  png_set_IHDR(png, info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), bitDepth,
               channels == 4 ? PNG_COLOR_TYPE_RGBA : PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  if (srgbChunk) png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
  if (metadata.dpi > 0) {
    const png_uint_32 perMetre = pixelsPerMetre(metadata.dpi);
    png_set_pHYs(png, info, perMetre, perMetre, PNG_RESOLUTION_METER);
  }
  png_text texts[2] = {};
  int count = 0;
  const auto addText = [&](const char* key, const std::string& text) {
    if (text.empty()) return;
    texts[count].compression = isAscii(text) ? PNG_TEXT_COMPRESSION_NONE : PNG_ITXT_COMPRESSION_NONE;
    texts[count].key = const_cast<png_charp>(key);
    texts[count].text = const_cast<png_charp>(text.c_str());
    texts[count].text_length = text.size();
    ++count;
  };
  addText("Software", metadata.software);
  addText("Comment", metadata.command);
  if (count > 0) png_set_text(png, info, texts, count);
  png_write_info(png, info);
}

// Returns false with error->text set when libpng fails (a failed write leaves the reason in `file`).
bool encodePng(AtomicFileWriter* file, int width, int height, int channels, bool srgbChunk, int bitDepth,
               const std::uint8_t* samples, const ImageMetadata& metadata, PngErrorText* error) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, error->text, onPngError, onPngWarning);
  if (png == nullptr) return false;
  png_infop info = png_create_info_struct(png);
  if (info == nullptr) {
    png_destroy_write_struct(&png, nullptr);
    return false;
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_set_write_fn(png, file, onPngWrite, onPngFlush);
  writePngHeader(png, info, width, height, channels, srgbChunk, bitDepth, metadata);
  const std::size_t stride = static_cast<std::size_t>(width) * static_cast<std::size_t>(channels) *
                             static_cast<std::size_t>(bitDepth / 8);
  for (int y = 0; y < height; ++y) {
    png_write_row(png, samples + stride * static_cast<std::size_t>(y));
  }
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return true;
}

struct PngSize {
  png_uint_32 width = 0, height = 0;
  bool alpha = false, srgb = false;
};

// Decodes to RGBA of 8-bit samples, or with `keep16` of 16-bit samples in the host's byte order (8-bit
// files widened, v * 257). Returns false with error->text on failure.
bool decodePng(std::FILE* stream, bool keep16, std::vector<std::uint8_t>* pixels, PngSize* size,
               PngErrorText* error) {
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, error->text, onPngError, onPngWarning);
  if (png == nullptr) return false;
  png_infop info = png_create_info_struct(png);
  if (info == nullptr) {
    png_destroy_read_struct(&png, nullptr, nullptr);
    return false;
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    return false;
  }
  png_init_io(png, stream);
  png_set_user_limits(png, kMaxImageSide, kMaxImageSide);
  png_read_info(png, info);
  size->width = png_get_image_width(png, info);
  size->height = png_get_image_height(png, info);
  size->alpha = (png_get_color_type(png, info) & PNG_COLOR_MASK_ALPHA) != 0 ||
                png_get_valid(png, info, PNG_INFO_tRNS) != 0;
  size->srgb = png_get_valid(png, info, PNG_INFO_sRGB) != 0;
  if (static_cast<std::uint64_t>(size->width) * size->height > kMaxReadPixels) {
    std::snprintf(error->text, sizeof(error->text), "image too large: %ux%u pixels (at most %llu)",
                  size->width, size->height, static_cast<unsigned long long>(kMaxReadPixels));
    png_destroy_read_struct(&png, &info, nullptr);
    return false;
  }
  png_set_expand(png);  // palette -> RGB, grey < 8 bits -> 8 bits, tRNS -> alpha
  if (keep16) {
    png_set_expand_16(png);
    png_set_swap(png);  // PNG stores big-endian samples
  } else {
    png_set_strip_16(png);
  }
  png_set_gray_to_rgb(png);
  png_set_add_alpha(png, keep16 ? 0xffff : 0xff, PNG_FILLER_AFTER);
  const int passes = png_set_interlace_handling(png);
  png_read_update_info(png, info);
  const std::size_t stride = static_cast<std::size_t>(size->width) * 4 * (keep16 ? 2 : 1);
  if (png_get_rowbytes(png, info) != stride) png_error(png, "unexpected row layout after transforms");
  pixels->resize(stride * size->height);
  for (int pass = 0; pass < passes; ++pass) {
    for (png_uint_32 y = 0; y < size->height; ++y) {
      png_read_row(png, pixels->data() + stride * y, nullptr);
    }
  }
  png_read_end(png, nullptr);
  png_destroy_read_struct(&png, &info, nullptr);
  return true;
}

struct FileCloser {
  void operator()(std::FILE* f) const { std::fclose(f); }
};

}  // namespace

PngRowEncoder::PngRowEncoder(AtomicFileWriter& file, int width, int height, int channels, bool srgbChunk,
                             int bitDepth, const ImageMetadata& metadata)
    : file_(file) {
  if (!start(width, height, channels, srgbChunk, bitDepth, metadata)) {
    destroy();  // no destructor runs after a throwing constructor
    fail();
  }
}

PngRowEncoder::~PngRowEncoder() { destroy(); }

void PngRowEncoder::destroy() noexcept {
  if (png_ != nullptr) png_destroy_write_struct(&png_, info_ != nullptr ? &info_ : nullptr);
  png_ = nullptr;
  info_ = nullptr;
}

bool PngRowEncoder::start(int width, int height, int channels, bool srgbChunk, int bitDepth,
                          const ImageMetadata& metadata) {
  png_ = png_create_write_struct(PNG_LIBPNG_VER_STRING, errorText_, onPngError, onPngWarning);
  if (png_ == nullptr) return false;
  info_ = png_create_info_struct(png_);
  if (info_ == nullptr) return false;
  if (setjmp(png_jmpbuf(png_))) return false;
  png_set_write_fn(png_, &file_, onPngWrite, onPngFlush);
  writePngHeader(png_, info_, width, height, channels, srgbChunk, bitDepth, metadata);
  return true;
}

bool PngRowEncoder::row(const std::uint8_t* samples) {
  if (setjmp(png_jmpbuf(png_))) return false;
  png_write_row(png_, samples);
  return true;
}

bool PngRowEncoder::end() {
  if (setjmp(png_jmpbuf(png_))) return false;
  png_write_end(png_, nullptr);
  return true;
}

void PngRowEncoder::writeRow(const std::uint8_t* samples) {
  if (!row(samples)) fail();
}

void PngRowEncoder::finish() {
  if (!end()) fail();
}

void PngRowEncoder::fail() {
  file_.throwIfFailed();  // a failed write, with its reason
  file_.discard();
  throw InputError(SourceLocation{file_.targetPath()}, fmt::format("PNG encoding failed: {}", errorText_));
}

void writePng(const std::string& path, const Image& image, const ImageWriteOptions& options) {
  if (image.empty()) throw InputError(SourceLocation{path}, "cannot write an empty (0-pixel) PNG");
  const bool alpha = options.alpha == AlphaChannel::Always ||
                     (options.alpha == AlphaChannel::Auto && image.hasTransparency());
  const int channels = alpha ? 4 : 3;
  const bool srgb = options.curve == TransferCurve::Srgb;
  if (options.bitDepth == 16) {
    const std::vector<std::uint8_t> samples = encodeImage16(image, options.curve, channels);
    writePngSamples(path, image.width(), image.height(), channels, srgb, 16, samples.data(),
                    options.metadata);
    return;
  }
  const std::vector<std::uint8_t> samples = encodeImage8(image, options.curve, channels);
  writePng8(path, image.width(), image.height(), channels, srgb, samples.data(), options.metadata);
}

void writePng8(const std::string& path, int width, int height, int channels, bool srgbChunk,
               const std::uint8_t* samples, const ImageMetadata& metadata) {
  writePngSamples(path, width, height, channels, srgbChunk, 8, samples, metadata);
}

void writePngSamples(const std::string& path, int width, int height, int channels, bool srgbChunk,
                     int bitDepth, const std::uint8_t* samples, const ImageMetadata& metadata) {
  if (width <= 0 || height <= 0)
    throw InputError(SourceLocation{path}, "cannot write an empty (0-pixel) PNG");
  AtomicFileWriter file(path);
  PngErrorText error;
  const bool ok = encodePng(&file, width, height, channels, srgbChunk, bitDepth, samples, metadata, &error);
  if (!ok && !file.failed()) {
    file.discard();
    throw InputError(SourceLocation{path}, fmt::format("PNG encoding failed: {}", error.text));
  }
  file.commit();  // reports a failed write with its reason
}

namespace {

// The file's pixels as RGBA samples of 8 bits, or of 16 bits in the host's order with `keep16`.
std::vector<std::uint8_t> readPngSamples(const std::string& path, bool keep16, PngSize& size) {
  std::unique_ptr<std::FILE, FileCloser> stream(std::fopen(path.c_str(), "rb"));
  if (!stream) {
    throw InputError(SourceLocation{path}, fmt::format("cannot open the file: {}", std::strerror(errno)));
  }
  png_byte signature[8] = {};
  errno = 0;
  const std::size_t got = std::fread(signature, 1, sizeof signature, stream.get());
  if (got != sizeof signature && std::ferror(stream.get())) {  // e.g. a folder
    throw InputError(SourceLocation{path}, fmt::format("cannot read the file: {}", std::strerror(errno)));
  }
  if (got != sizeof signature || png_sig_cmp(signature, 0, sizeof signature) != 0) {
    throw InputError(SourceLocation{path, 0, 0, 0}, "not a PNG file (the 8-byte PNG signature is missing)");
  }
  std::rewind(stream.get());
  std::vector<std::uint8_t> pixels;
  PngErrorText error;
  if (!decodePng(stream.get(), keep16, &pixels, &size, &error)) {
    throw InputError(SourceLocation{path}, fmt::format("unreadable PNG: {}", error.text));
  }
  return pixels;
}

}  // namespace

Image readPng16(const std::string& path, TransferCurve curve) {
  PngSize size;
  const std::vector<std::uint8_t> bytes = readPngSamples(path, true, size);
  Image image(static_cast<int>(size.width), static_cast<int>(size.height));
  std::size_t i = 0;
  const auto next = [&] {
    std::uint16_t v = 0;
    std::memcpy(&v, bytes.data() + 2 * i++, 2);
    return v;
  };
  for (Rgba& pixel : image.pixels()) {
    const std::uint16_t r = next(), g = next(), b = next(), a = next();
    pixel = {decode16(r, curve), decode16(g, curve), decode16(b, curve), decode16(a)};
  }
  return image;
}

Image readPng(const std::string& path, TransferCurve curve, PngDescription* description) {
  PngSize size;
  const std::vector<std::uint8_t> pixels = readPngSamples(path, false, size);
  if (description != nullptr) *description = PngDescription{size.alpha, size.srgb};
  Image image(static_cast<int>(size.width), static_cast<int>(size.height));
  const std::uint8_t* p = pixels.data();
  for (Rgba& pixel : image.pixels()) {
    pixel = {decode8(p[0], curve), decode8(p[1], curve), decode8(p[2], curve), decode8(p[3])};
    p += 4;
  }
  return image;
}

}  // namespace lancer
