// WebP through libwebp (the simple encoding API) and libwebpmux, which adds the EXIF chunk that holds
// the DPI and how the picture was made.
#include <fmt/format.h>
#include <webp/encode.h>
#include <webp/mux.h>

#include <memory>

#include "lancer/image/atomic_file.hpp"
#include "lancer/image/image_io.hpp"
#include "lancer/util/input_error.hpp"

namespace lancer {
namespace {

struct WebpFree {
  void operator()(std::uint8_t* p) const { WebPFree(p); }
};
struct MuxDelete {
  void operator()(WebPMux* mux) const { WebPMuxDelete(mux); }
};

}  // namespace

void writeWebp8(const std::string& path, int width, int height, int channels, const std::uint8_t* samples,
                int quality, bool lossless, const ImageMetadata& metadata) {
  if (width <= 0 || height <= 0)
    throw InputError(SourceLocation{path}, "cannot write an empty (0-pixel) WebP");
  requireImageSize(path, ImageFormat::Webp, width, height);
  requireImageQuality(quality, SourceLocation{path});
  AtomicFileWriter file(path);  // a bad folder fails before the encoding
  // The advanced API: lossless files keep the colour under fully transparent pixels too (`exact`), so
  // that they decode to every sample written.
  WebPConfig config;
  WebPPicture picture;
  if (!WebPConfigInit(&config) || !WebPPictureInit(&picture)) {
    file.discard();
    throw InputError(SourceLocation{path}, "WebP encoding failed: libwebp version mismatch");
  }
  config.quality = static_cast<float>(quality);
  if (lossless) {
    config.lossless = 1;
    config.exact = 1;
    config.quality = 75;  // for lossless: the effort, libwebp's default
  }
  picture.use_argb = lossless ? 1 : 0;
  picture.width = width;
  picture.height = height;
  WebPMemoryWriter memory;
  WebPMemoryWriterInit(&memory);
  picture.writer = WebPMemoryWrite;
  picture.custom_ptr = &memory;
  const int stride = width * channels;
  const bool imported = channels == 4 ? WebPPictureImportRGBA(&picture, samples, stride)
                                      : WebPPictureImportRGB(&picture, samples, stride);
  const bool encodedOk = imported && WebPEncode(&config, &picture);
  WebPPictureFree(&picture);
  const std::unique_ptr<std::uint8_t, WebpFree> encoded(memory.mem);
  const std::size_t size = memory.size;
  if (!encodedOk || size == 0) {
    file.discard();
    throw InputError(SourceLocation{path}, fmt::format("WebP encoding failed (libwebp error {})",
                                                       static_cast<int>(picture.error_code)));
  }
  const std::vector<std::uint8_t> exif = exifBlock(metadata);
  if (exif.empty()) {
    file.write(encoded.get(), size);
    file.commit();
    return;
  }
  const WebPData image{encoded.get(), size};
  const std::unique_ptr<WebPMux, MuxDelete> mux(WebPMuxCreate(&image, 0));
  const WebPData exifData{exif.data(), exif.size()};
  WebPData assembled{nullptr, 0};
  if (!mux || WebPMuxSetChunk(mux.get(), "EXIF", &exifData, 0) != WEBP_MUX_OK ||
      WebPMuxAssemble(mux.get(), &assembled) != WEBP_MUX_OK) {
    file.discard();
    throw InputError(SourceLocation{path}, "WebP encoding failed: the EXIF chunk could not be added");
  }
  file.write(assembled.bytes, assembled.size);
  WebPDataClear(&assembled);
  file.commit();
}

}  // namespace lancer
