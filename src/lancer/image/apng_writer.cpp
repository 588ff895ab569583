#include "lancer/image/apng_writer.hpp"

#include <fmt/format.h>
#include <zlib.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <vector>

#include "lancer/image/atomic_file.hpp"
#include "lancer/util/input_error.hpp"

namespace lancer {

ApngDelay apngFrameDelay(double fps) {
  if (fps == std::floor(fps) && fps >= 1 && fps <= 65535) return {1, static_cast<int>(fps)};
  const double milliseconds = std::clamp(std::round(1000.0 / fps), 1.0, 65535.0);
  return {static_cast<int>(milliseconds), 1000};
}

namespace {

constexpr std::array<std::uint8_t, 8> kPngSignature = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

void putU32(std::vector<std::uint8_t>& out, std::uint32_t v) {
  out.push_back(static_cast<std::uint8_t>(v >> 24));
  out.push_back(static_cast<std::uint8_t>(v >> 16));
  out.push_back(static_cast<std::uint8_t>(v >> 8));
  out.push_back(static_cast<std::uint8_t>(v));
}

void putU16(std::vector<std::uint8_t>& out, int v) {
  out.push_back(static_cast<std::uint8_t>(v >> 8));
  out.push_back(static_cast<std::uint8_t>(v));
}

int paeth(int a, int b, int c) {
  const int p = a + b - c;
  const int pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
  if (pa <= pb && pa <= pc) return a;
  return pb <= pc ? b : c;
}

// Filters every row with the PNG filter whose output has the smallest sum of absolute values (as
// signed bytes): the heuristic of the PNG specification, section 12.8, and of libpng.
std::vector<std::uint8_t> filterRows(const std::vector<std::uint8_t>& samples, int width, int height,
                                     int channels) {
  const std::size_t stride = static_cast<std::size_t>(width) * static_cast<std::size_t>(channels);
  const std::size_t bpp = static_cast<std::size_t>(channels);
  std::vector<std::uint8_t> out;
  out.reserve((stride + 1) * static_cast<std::size_t>(height));
  const std::vector<std::uint8_t> zeroRow(stride, 0);
  std::array<std::vector<std::uint8_t>, 5> candidates;
  for (auto& c : candidates) c.resize(stride);
  for (int y = 0; y < height; ++y) {
    const std::uint8_t* row = samples.data() + stride * static_cast<std::size_t>(y);
    const std::uint8_t* up = y > 0 ? row - stride : zeroRow.data();
    std::size_t best = 0;
    std::uint64_t bestCost = ~std::uint64_t{0};
    for (std::size_t type = 0; type < 5; ++type) {
      std::vector<std::uint8_t>& f = candidates[type];
      std::uint64_t cost = 0;
      for (std::size_t i = 0; i < stride; ++i) {
        const int a = i >= bpp ? row[i - bpp] : 0, b = up[i], c = i >= bpp ? up[i - bpp] : 0;
        const int predictor = type == 0   ? 0
                              : type == 1 ? a
                              : type == 2 ? b
                              : type == 3 ? (a + b) / 2
                                          : paeth(a, b, c);
        f[i] = static_cast<std::uint8_t>(row[i] - predictor);
        cost += static_cast<std::uint64_t>(std::abs(static_cast<int>(static_cast<std::int8_t>(f[i]))));
      }
      if (cost < bestCost) {
        bestCost = cost;
        best = type;
      }
    }
    out.push_back(static_cast<std::uint8_t>(best));
    out.insert(out.end(), candidates[best].begin(), candidates[best].end());
  }
  return out;
}

std::vector<std::uint8_t> deflate(const std::vector<std::uint8_t>& data) {
  uLongf size = compressBound(static_cast<uLong>(data.size()));
  std::vector<std::uint8_t> out(size);
  if (compress2(out.data(), &size, data.data(), static_cast<uLong>(data.size()), Z_DEFAULT_COMPRESSION) !=
      Z_OK)
    throw std::runtime_error("zlib compress2 failed");
  out.resize(size);
  return out;
}

}  // namespace

struct ApngWriter::Encoder {
  std::string path;
  int width, height, frameCount;
  ApngOptions options;
  AtomicFileWriter file;
  int framesWritten = 0;
  std::uint32_t sequence = 0;  // fcTL and fdAT share one sequence, from 0
  bool finished = false;

  Encoder(std::string p, int w, int h, int n, const ApngOptions& o)
      : path(p), width(w), height(h), frameCount(n), options(o), file(std::move(p)) {}

  // length, type, data, CRC-32 of type and data (PNG specification, section 5.3).
  void putChunk(const char (&type)[5], const std::uint8_t* data, std::size_t size) {
    std::vector<std::uint8_t> head;
    putU32(head, static_cast<std::uint32_t>(size));
    head.insert(head.end(), type, type + 4);
    uLong crc = crc32(0L, head.data() + 4, 4);
    if (size > 0) crc = crc32(crc, data, static_cast<uInt>(size));
    std::vector<std::uint8_t> tail;
    putU32(tail, static_cast<std::uint32_t>(crc));
    file.write(head);
    if (size > 0) file.write(data, size);
    file.write(tail);
  }
  void putChunk(const char (&type)[5], const std::vector<std::uint8_t>& data) {
    putChunk(type, data.data(), data.size());
  }

  void putHeader() {
    file.write(kPngSignature);
    std::vector<std::uint8_t> ihdr;
    putU32(ihdr, static_cast<std::uint32_t>(width));
    putU32(ihdr, static_cast<std::uint32_t>(height));
    ihdr.push_back(8);                      // bit depth
    ihdr.push_back(options.alpha ? 6 : 2);  // colour type: RGBA or RGB
    ihdr.insert(ihdr.end(), {0, 0, 0});     // deflate, adaptive filtering, no interlace
    putChunk("IHDR", ihdr);
    if (options.curve == TransferCurve::Srgb) putChunk("sRGB", std::vector<std::uint8_t>{0});  // perceptual
    std::vector<std::uint8_t> actl;
    putU32(actl, static_cast<std::uint32_t>(frameCount));
    putU32(actl, static_cast<std::uint32_t>(options.loopCount));
    putChunk("acTL", actl);
  }

  void putFrameControl() {
    const ApngDelay delay = apngFrameDelay(options.fps);
    std::vector<std::uint8_t> fctl;
    putU32(fctl, sequence++);
    putU32(fctl, static_cast<std::uint32_t>(width));
    putU32(fctl, static_cast<std::uint32_t>(height));
    putU32(fctl, 0);  // x offset
    putU32(fctl, 0);  // y offset
    putU16(fctl, delay.numerator);
    putU16(fctl, delay.denominator);
    fctl.push_back(0);  // dispose_op NONE
    fctl.push_back(0);  // blend_op SOURCE: every frame replaces the canvas, alpha included
    putChunk("fcTL", fctl);
  }
};

ApngWriter::ApngWriter(std::string path, int width, int height, int frameCount, ApngOptions options) {
  if (width < 1 || height < 1 || width > kMaxImageSide || height > kMaxImageSide)
    throw InputError(SourceLocation{path},
                     fmt::format("an animated PNG must be 1..{} pixels on each side, not {}x{}",
                                 kMaxImageSide, width, height));
  if (frameCount < 1) throw InputError(SourceLocation{path}, "an animated PNG needs at least one frame");
  if (!(options.fps > 0) || !std::isfinite(options.fps))
    throw InputError(SourceLocation{path},
                     fmt::format("the frame rate must be positive, not {}", options.fps));
  if (options.loopCount < 0 || options.loopCount > 65535)
    throw InputError(SourceLocation{path},
                     fmt::format("the play count must be 0 (forever) to 65535, not {}", options.loopCount));
  encoder_ = std::make_unique<Encoder>(std::move(path), width, height, frameCount, options);
  encoder_->putHeader();
}

ApngWriter::~ApngWriter() = default;

void ApngWriter::addFrame(const Image& frame) {
  Encoder& e = *encoder_;
  if (e.finished || e.framesWritten == e.frameCount)
    throw std::logic_error("ApngWriter::addFrame(): more frames than announced, or after finish()");
  if (frame.width() != e.width || frame.height() != e.height)
    throw std::invalid_argument(fmt::format("APNG frame is {}x{}, the animation {}x{}", frame.width(),
                                            frame.height(), e.width, e.height));
  const int channels = e.options.alpha ? 4 : 3;
  const std::vector<std::uint8_t> compressed =
      deflate(filterRows(encodeImage8(frame, e.options.curve, channels), e.width, e.height, channels));
  e.putFrameControl();
  // A chunk holds at most 2^31 - 1 bytes; pieces of 1 MiB keep every chunk small whatever the size.
  constexpr std::size_t kPiece = std::size_t{1} << 20;
  for (std::size_t start = 0; start < compressed.size(); start += kPiece) {
    const std::size_t size = std::min(kPiece, compressed.size() - start);
    if (e.framesWritten == 0) {
      e.putChunk("IDAT", compressed.data() + start, size);  // the default image is the first frame
    } else {
      std::vector<std::uint8_t> fdat;
      fdat.reserve(size + 4);
      putU32(fdat, e.sequence++);
      fdat.insert(fdat.end(), compressed.begin() + static_cast<std::ptrdiff_t>(start),
                  compressed.begin() + static_cast<std::ptrdiff_t>(start + size));
      e.putChunk("fdAT", fdat);
    }
  }
  ++e.framesWritten;
}

void ApngWriter::finish() {
  Encoder& e = *encoder_;
  if (e.finished) throw std::logic_error("ApngWriter::finish() called twice");
  if (e.framesWritten != e.frameCount)
    throw std::logic_error(
        fmt::format("ApngWriter::finish() after {} of {} frames", e.framesWritten, e.frameCount));
  e.finished = true;
  e.putChunk("IEND", nullptr, 0);
  e.file.commit();
}

}  // namespace lancer
