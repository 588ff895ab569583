#include "lancer/image/gif_writer.hpp"

#include <fmt/format.h>
#include <gif_lib.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "lancer/image/atomic_file.hpp"
#include "lancer/image/palette_quantizer.hpp"
#include "lancer/util/input_error.hpp"

namespace lancer {

int gifFrameDelay(double fps) {
  const double hundredths = std::round(100.0 / fps);
  return static_cast<int>(std::clamp(hundredths, 2.0, 65535.0));
}

double gifActualFrameRate(double fps) { return 100.0 / gifFrameDelay(fps); }

namespace {

int gifOutput(GifFileType* gif, const GifByteType* data, int size) {
  auto* file = static_cast<AtomicFileWriter*>(gif->UserData);
  return file->write(data, static_cast<std::size_t>(size)) ? size : 0;
}

// A giflib colour map, padded with black to the power of two that GIF requires.
struct ColourMap {
  ColorMapObject* map = nullptr;
  explicit ColourMap(const Palette& palette) {
    int size = 2;
    while (size < static_cast<int>(palette.size())) size *= 2;
    std::vector<GifColorType> colours(static_cast<std::size_t>(size), GifColorType{0, 0, 0});
    for (std::size_t i = 0; i < palette.size(); ++i) colours[i] = {palette[i].r, palette[i].g, palette[i].b};
    map = GifMakeMapObject(size, colours.data());
    if (map == nullptr) throw std::bad_alloc();
  }
  ~ColourMap() { GifFreeMapObject(map); }
  ColourMap(const ColourMap&) = delete;
  ColourMap& operator=(const ColourMap&) = delete;
};

struct Rect {
  int x = 0, y = 0, width = 0, height = 0;
};

// The smallest rectangle where `indices` differs from `previous`; a 1x1 corner when nothing changed
// (a frame must still be written to keep the timing).
Rect changedRect(const std::vector<std::uint8_t>& indices, const std::vector<std::uint8_t>& previous,
                 int width, int height) {
  int x0 = width, x1 = -1, y0 = height, y1 = -1;
  for (int y = 0; y < height; ++y) {
    const std::size_t rowStart = static_cast<std::size_t>(y) * static_cast<std::size_t>(width);
    for (int x = 0; x < width; ++x) {
      if (indices[rowStart + static_cast<std::size_t>(x)] !=
          previous[rowStart + static_cast<std::size_t>(x)]) {
        x0 = std::min(x0, x);
        x1 = std::max(x1, x);
        y0 = std::min(y0, y);
        y1 = std::max(y1, y);
      }
    }
  }
  if (x1 < 0) return {0, 0, 1, 1};
  return {x0, y0, x1 - x0 + 1, y1 - y0 + 1};
}

}  // namespace

struct GifWriter::Encoder {
  std::string path;
  int width;
  int height;
  GifOptions options;
  int delay;
  AtomicFileWriter file;
  GifFileType* gif = nullptr;
  // Global palette: frames kept as 8-bit RGB until finish().
  PaletteBuilder paletteBuilder;
  std::vector<std::vector<std::uint8_t>> pendingFrames;
  std::vector<std::uint8_t> previousIndices;
  bool finished = false;

  Encoder(std::string p, int w, int h, const GifOptions& o)
      : path(p), width(w), height(h), options(o), delay(gifFrameDelay(o.fps)), file(std::move(p)) {}

  ~Encoder() {
    if (gif != nullptr) EGifCloseFile(gif, nullptr);
  }

  // Turns a giflib failure into an InputError: the write's own reason when writing failed.
  void check(int result, const char* step) {
    if (result != GIF_ERROR) return;
    const int code = gif != nullptr ? gif->Error : 0;
    if (gif != nullptr) EGifCloseFile(gif, nullptr);
    gif = nullptr;
    if (file.failed()) file.commit();  // throws with the write error (disk full, size limit, ...)
    file.discard();
    throw InputError(SourceLocation{path},
                     fmt::format("GIF encoding failed at {}: {}", step,
                                 GifErrorString(code) ? GifErrorString(code) : "unknown"));
  }

  void open(const Palette* globalPalette) {
    int error = 0;
    gif = EGifOpen(&file, gifOutput, &error);
    if (gif == nullptr) {
      throw InputError(SourceLocation{path}, fmt::format("GIF encoding failed: {}", GifErrorString(error)));
    }
    EGifSetGifVersion(gif, true);
    if (globalPalette != nullptr) {
      ColourMap map(*globalPalette);
      check(EGifPutScreenDesc(gif, width, height, 8, 0, map.map), "the screen descriptor");
    } else {
      check(EGifPutScreenDesc(gif, width, height, 8, 0, nullptr), "the screen descriptor");
    }
    if (options.loopCount != kGifPlayOnce) {
      // NETSCAPE2.0 application extension: sub-block id 1, then the loop count, little-endian.
      const GifByteType application[] = {'N', 'E', 'T', 'S', 'C', 'A', 'P', 'E', '2', '.', '0'};
      const GifByteType loop[] = {1, static_cast<GifByteType>(options.loopCount & 0xff),
                                  static_cast<GifByteType>((options.loopCount >> 8) & 0xff)};
      check(EGifPutExtensionLeader(gif, APPLICATION_EXT_FUNC_CODE), "the loop block");
      check(EGifPutExtensionBlock(gif, sizeof application, application), "the loop block");
      check(EGifPutExtensionBlock(gif, sizeof loop, loop), "the loop block");
      check(EGifPutExtensionTrailer(gif), "the loop block");
    }
  }

  void putFrame(std::vector<std::uint8_t>& indices, const Rect& rect, const Palette* localPalette) {
    GraphicsControlBlock control{};
    control.DisposalMode = DISPOSE_DO_NOT;
    control.UserInputFlag = false;
    control.DelayTime = delay;
    control.TransparentColor = NO_TRANSPARENT_COLOR;
    GifByteType extension[4];
    const std::size_t length = EGifGCBToExtension(&control, extension);
    check(EGifPutExtension(gif, GRAPHICS_EXT_FUNC_CODE, static_cast<int>(length), extension),
          "a frame's delay");
    if (localPalette != nullptr) {
      ColourMap map(*localPalette);
      check(EGifPutImageDesc(gif, rect.x, rect.y, rect.width, rect.height, false, map.map), "a frame header");
    } else {
      check(EGifPutImageDesc(gif, rect.x, rect.y, rect.width, rect.height, false, nullptr), "a frame header");
    }
    for (int y = rect.y; y < rect.y + rect.height; ++y) {
      GifPixelType* line = indices.data() + static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                           static_cast<std::size_t>(rect.x);
      check(EGifPutLine(gif, line, rect.width), "a frame's pixels");
    }
  }
};

GifWriter::GifWriter(std::string path, int width, int height, GifOptions options) {
  if (width < 1 || height < 1 || width > kMaxImageSide || height > kMaxImageSide) {
    throw InputError(SourceLocation{path}, fmt::format("a GIF must be 1..{} pixels on each side, not {}x{}",
                                                       kMaxImageSide, width, height));
  }
  if (!(options.fps > 0) || !std::isfinite(options.fps)) {
    throw InputError(SourceLocation{path},
                     fmt::format("the frame rate must be positive, not {}", options.fps));
  }
  if (options.loopCount < kGifPlayOnce || options.loopCount > 65535) {
    throw InputError(SourceLocation{path},
                     fmt::format("the loop count must be 0 (forever) to 65535, not {}", options.loopCount));
  }
  encoder_ = std::make_unique<Encoder>(std::move(path), width, height, options);
  if (options.palette == GifPalette::PerFrame) encoder_->open(nullptr);
}

GifWriter::~GifWriter() = default;

int GifWriter::frameDelay() const { return encoder_->delay; }

void GifWriter::addFrame(const Image& frame) {
  Encoder& e = *encoder_;
  if (e.finished) throw std::logic_error("GifWriter::addFrame() after finish()");
  if (frame.width() != e.width || frame.height() != e.height) {
    throw std::invalid_argument(fmt::format("GIF frame is {}x{}, the animation {}x{}", frame.width(),
                                            frame.height(), e.width, e.height));
  }
  std::vector<std::uint8_t> rgb = encodeImage8(frame, e.options.curve, 3);
  if (e.options.palette == GifPalette::Global) {
    e.paletteBuilder.add(rgb);
    e.pendingFrames.push_back(std::move(rgb));
  } else {
    PaletteBuilder builder;
    builder.add(rgb);
    const Palette palette = builder.build();
    NearestColour nearest(palette);
    std::vector<std::uint8_t> indices(rgb.size() / 3);
    mapToPalette(rgb, e.width, e.height, nearest, builder.exact() ? Dither::None : e.options.dither, indices);
    e.putFrame(indices, {0, 0, e.width, e.height}, &palette);
  }
  ++frameCount_;
}

void GifWriter::finish() {
  Encoder& e = *encoder_;
  if (frameCount_ == 0) throw std::logic_error("GifWriter::finish() with no frames");
  if (e.finished) throw std::logic_error("GifWriter::finish() called twice");
  e.finished = true;
  if (e.options.palette == GifPalette::Global) {
    const Palette palette = e.paletteBuilder.build();
    const Dither dither = e.paletteBuilder.exact() ? Dither::None : e.options.dither;
    e.open(&palette);
    NearestColour nearest(palette);
    std::vector<std::uint8_t> indices(static_cast<std::size_t>(e.width) * static_cast<std::size_t>(e.height));
    for (std::vector<std::uint8_t>& rgb : e.pendingFrames) {
      mapToPalette(rgb, e.width, e.height, nearest, dither, indices);
      const Rect rect = e.previousIndices.empty()
                            ? Rect{0, 0, e.width, e.height}
                            : changedRect(indices, e.previousIndices, e.width, e.height);
      e.putFrame(indices, rect, nullptr);
      e.previousIndices.swap(indices);
      indices.resize(e.previousIndices.size());
      std::vector<std::uint8_t>().swap(rgb);  // release the frame as soon as it is written
    }
  }
  int error = 0;
  GifFileType* gif = e.gif;
  e.gif = nullptr;
  if (EGifCloseFile(gif, &error) == GIF_ERROR && !e.file.failed()) {
    e.file.discard();
    throw InputError(SourceLocation{e.path}, fmt::format("GIF encoding failed: {}", GifErrorString(error)));
  }
  e.file.commit();
}

}  // namespace lancer
