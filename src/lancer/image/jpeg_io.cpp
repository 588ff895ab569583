// JPEG through libjpeg(-turbo). libjpeg reports errors by calling error_exit, which must not return:
// ours longjmps back, so the function that calls libjpeg holds only trivially destructible locals;
// the C++ side (exceptions, the atomic file) stays in the caller.
#include <fmt/format.h>
#include <jpeglib.h>

#include <cmath>
#include <csetjmp>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <span>
#include <vector>

#include "lancer/image/atomic_file.hpp"
#include "lancer/image/image_io.hpp"
#include "lancer/util/input_error.hpp"

namespace lancer {
namespace {

struct JpegError {
  jpeg_error_mgr manager;  // first: libjpeg hands back a pointer to it
  std::jmp_buf jump;
  char text[JMSG_LENGTH_MAX];
};

void onJpegError(j_common_ptr info) {
  auto* error = reinterpret_cast<JpegError*>(info->err);
  (*info->err->format_message)(info, error->text);
  std::longjmp(error->jump, 1);
}
void onJpegMessage(j_common_ptr, int) {}  // the library never prints

// Encodes into `*out` (malloc'ed by libjpeg's memory destination; the caller frees it). Returns false
// with error->text set on failure. A row of 4 channels is copied to `rgb` (3 channels) first.
bool encodeJpeg(int width, int height, int channels, const std::uint8_t* samples, int quality, double dpi,
                const std::string* comment, std::uint8_t* rgb, unsigned char** out, unsigned long* size,
                JpegError* error) {
  jpeg_compress_struct info;
  info.err = jpeg_std_error(&error->manager);
  error->manager.error_exit = onJpegError;
  error->manager.emit_message = onJpegMessage;
  if (setjmp(error->jump)) {
    jpeg_destroy_compress(&info);
    return false;
  }
  jpeg_create_compress(&info);
  jpeg_mem_dest(&info, out, size);
  info.image_width = static_cast<JDIMENSION>(width);
  info.image_height = static_cast<JDIMENSION>(height);
  info.input_components = 3;
  info.in_color_space = JCS_RGB;
  jpeg_set_defaults(&info);
  jpeg_set_quality(&info, quality, TRUE);
  info.optimize_coding = TRUE;  // Huffman tables fitted to the picture: a few % smaller, same pixels
  if (dpi > 0) {
    info.write_JFIF_header = TRUE;
    info.density_unit = 1;  // dots per inch (JFIF 1.02)
    info.X_density = info.Y_density = static_cast<UINT16>(std::lround(dpi));
  }
  jpeg_start_compress(&info, TRUE);
  if (comment != nullptr && !comment->empty())
    jpeg_write_marker(&info, JPEG_COM, reinterpret_cast<const JOCTET*>(comment->data()),
                      static_cast<unsigned int>(comment->size()));
  const std::size_t stride = static_cast<std::size_t>(width) * static_cast<std::size_t>(channels);
  while (info.next_scanline < info.image_height) {
    const std::uint8_t* row = samples + stride * info.next_scanline;
    if (channels == 4) {
      for (int x = 0; x < width; ++x) std::memcpy(rgb + 3 * x, row + 4 * x, 3);
      row = rgb;
    }
    JSAMPROW rows[1] = {const_cast<JSAMPROW>(row)};
    jpeg_write_scanlines(&info, rows, 1);
  }
  jpeg_finish_compress(&info);
  jpeg_destroy_compress(&info);
  return true;
}

}  // namespace

void writeJpeg8(const std::string& path, int width, int height, int channels, const std::uint8_t* samples,
                int quality, const ImageMetadata& metadata) {
  if (width <= 0 || height <= 0)
    throw InputError(SourceLocation{path}, "cannot write an empty (0-pixel) JPEG");
  requireImageSize(path, ImageFormat::Jpeg, width, height);
  requireImageQuality(quality, SourceLocation{path});
  AtomicFileWriter file(path);  // a bad folder fails before the encoding
  // The COM marker holds at most 65533 bytes; a longer command line is cut there.
  std::string comment = metadata.software;
  if (!metadata.command.empty()) comment += (comment.empty() ? "" : ": ") + metadata.command;
  if (comment.size() > 65533) comment.resize(65533);
  std::vector<std::uint8_t> rgb(channels == 4 ? static_cast<std::size_t>(width) * 3 : 0);
  unsigned char* encoded = nullptr;
  unsigned long size = 0;
  JpegError error{};
  const bool ok = encodeJpeg(width, height, channels, samples, quality, metadata.dpi, &comment, rgb.data(),
                             &encoded, &size, &error);
  if (!ok) {
    std::free(encoded);
    file.discard();
    throw InputError(SourceLocation{path}, fmt::format("JPEG encoding failed: {}", error.text));
  }
  file.write(encoded, size);
  std::free(encoded);
  file.commit();
}

}  // namespace lancer
