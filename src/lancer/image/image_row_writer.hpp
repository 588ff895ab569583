// Still images written row by row, top to bottom, as a renderer finishes them, so a picture of any
// height needs memory for a row, not for the image: PNG (libpng's row interface), BMP and PPM. The
// file holds exactly the bytes writeImage writes for the whole image, and is published atomically.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "lancer/image/atomic_file.hpp"
#include "lancer/image/image.hpp"
#include "lancer/image/image_io.hpp"

namespace lancer {

class PngRowEncoder;

class ImageRowWriter {
 public:
  // True for the formats that can be written row by row: PNG, BMP, PPM (not GIF, whose palette
  // needs every pixel first, EXR, written whole with its layers, nor JPEG and WebP, encoded whole).
  static bool streams(ImageFormat format) {
    return format == ImageFormat::Png || format == ImageFormat::Bmp || format == ImageFormat::Ppm;
  }

  // Creates the temporary file and writes the header now, so a bad path fails before rendering.
  // `options.alpha` must be Always or Never (Auto would need every pixel; std::invalid_argument).
  // Throws InputError naming the file for an unknown extension, a .gif, a BMP over 4 GiB, or I/O.
  ImageRowWriter(const std::string& path, int width, int height, const ImageWriteOptions& options);
  // Without commit(): the temporary file is removed and an existing file is untouched.
  ~ImageRowWriter();
  ImageRowWriter(const ImageRowWriter&) = delete;
  ImageRowWriter& operator=(const ImageRowWriter&) = delete;

  // The next rows.height() rows (rows.width() must be the image width). Throws InputError at the
  // first failed write, after removing the temporary file.
  void writeRows(const Image& rows);
  void writeRow(std::span<const Rgba> row);
  // After the last row: publishes the file over the target. Throws InputError.
  void commit();

  int rowsWritten() const { return rowsWritten_; }
  const std::string& path() const { return file_.targetPath(); }

 private:
  ImageFormat format_;  // first: a refused format fails before the temporary file exists
  AtomicFileWriter file_;
  int width_, height_;
  TransferCurve curve_;
  int channels_;  // in the file: 3, or 4 for PNG with alpha
  int bitDepth_;  // 8, or 16 for PNG
  std::unique_ptr<PngRowEncoder> png_;
  std::uint64_t bmpPixelsOffset_ = 0;  // BMP: where the bottom row starts
  std::vector<std::uint8_t> encoded_;  // one row in the file's layout
  int rowsWritten_ = 0;
};

}  // namespace lancer
