#include "lancer/image/image_row_writer.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "lancer/image/bmp_ppm_layout.hpp"
#include "lancer/image/png_row_encoder.hpp"
#include "lancer/util/input_error.hpp"

namespace lancer {
namespace {

ImageFormat streamedFormat(const std::string& path, const ImageWriteOptions& options) {
  const ImageFormat format = imageFormatFromPath(path);
  requireBitDepth(path, format, options.bitDepth);
  if (!ImageRowWriter::streams(format))
    throw InputError(SourceLocation{path},
                     format == ImageFormat::Gif
                         ? "a GIF cannot be written row by row (its palette needs every pixel)"
                         : "this format is written whole, not row by row (PNG, BMP and PPM stream)");
  return format;
}

int fileChannels(ImageFormat format, const ImageWriteOptions& options) {
  if (options.alpha == AlphaChannel::Auto)
    throw std::invalid_argument("ImageRowWriter needs AlphaChannel::Always or Never, not Auto");
  return format == ImageFormat::Png && options.alpha == AlphaChannel::Always ? 4 : 3;
}

}  // namespace

ImageRowWriter::ImageRowWriter(const std::string& path, int width, int height,
                               const ImageWriteOptions& options)
    : format_(streamedFormat(path, options)),
      file_(path),
      width_(width),
      height_(height),
      curve_(options.curve),
      channels_(fileChannels(format_, options)),
      bitDepth_(options.bitDepth) {
  if (width < 1 || height < 1 || width > kMaxImageSide || height > kMaxImageSide)
    throw std::invalid_argument(fmt::format("ImageRowWriter: bad size {}x{}", width, height));
  switch (format_) {
    case ImageFormat::Png:
      encoded_.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(channels_) *
                      static_cast<std::size_t>(bitDepth_ / 8));
      png_ = std::make_unique<PngRowEncoder>(file_, width, height, channels_, curve_ == TransferCurve::Srgb,
                                             bitDepth_, options.metadata);
      break;
    case ImageFormat::Bmp: {
      std::vector<std::uint8_t> header;
      try {
        header = bmpHeader(width, height);
      } catch (const InputError& e) {
        throw InputError(SourceLocation{path}, e.message());
      }
      bmpPixelsOffset_ = header.size();
      encoded_.resize(static_cast<std::size_t>(bmpRowBytes(width)));
      file_.write(header);
      break;
    }
    case ImageFormat::Ppm: {
      const std::string header = ppmHeader(width, height);
      encoded_.resize(static_cast<std::size_t>(width) * 3);
      file_.write(header.data(), header.size());
      break;
    }
    default:
      break;  // refused by streamedFormat
  }
  file_.throwIfFailed();
}

ImageRowWriter::~ImageRowWriter() = default;

void ImageRowWriter::writeRows(const Image& rows) {
  for (int y = 0; y < rows.height(); ++y) writeRow(rows.row(y));
}

void ImageRowWriter::writeRow(std::span<const Rgba> row) {
  if (static_cast<int>(row.size()) != width_ || rowsWritten_ >= height_)
    throw std::invalid_argument(fmt::format("ImageRowWriter: row {} of {} pixels for a {}x{} image",
                                            rowsWritten_, row.size(), width_, height_));
  switch (format_) {
    case ImageFormat::Png:
      if (bitDepth_ == 16)
        encodeRow16(row, curve_, channels_, encoded_.data());
      else
        encodeRow8(row, curve_, channels_, encoded_.data());
      png_->writeRow(encoded_.data());
      break;
    case ImageFormat::Bmp: {
      // BMP stores rows bottom-up: row y goes where the file's row height - 1 - y starts. The first
      // row written is the file's last, so the file has its final size from then on.
      encodeBmpRow(row, curve_, encoded_.data());
      const std::uint64_t storedRow = static_cast<std::uint64_t>(height_ - 1 - rowsWritten_);
      file_.writeAt(bmpPixelsOffset_ + storedRow * encoded_.size(), encoded_.data(), encoded_.size());
      break;
    }
    case ImageFormat::Ppm:
      encodeRow8(row, curve_, 3, encoded_.data());
      file_.write(encoded_.data(), encoded_.size());
      break;
    default:
      break;  // refused by streamedFormat
  }
  file_.throwIfFailed();
  ++rowsWritten_;
}

void ImageRowWriter::commit() {
  if (rowsWritten_ != height_) {
    file_.discard();
    throw std::logic_error(fmt::format("ImageRowWriter: commit after {} of {} rows", rowsWritten_, height_));
  }
  if (png_) png_->finish();
  file_.commit();
}

}  // namespace lancer
