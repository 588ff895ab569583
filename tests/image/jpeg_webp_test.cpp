// JPEG and WebP stills written by lancer and decoded by the reference libraries (libjpeg, libwebp):
// the pictures come back within the lossy codecs' tolerance (WebP lossless: exactly, alpha included),
// with the DPI and the provenance where each format keeps them; a refused quality or a folder that
// cannot be written leaves nothing behind.
#include <gtest/gtest.h>
#include <jpeglib.h>
#include <webp/decode.h>
#include <webp/mux.h>

#include <csetjmp>
#include <cstdio>
#include <string>
#include <vector>

#include "lancer/image/image_io.hpp"
#include "lancer/image/pixel_encoding.hpp"
#include "support/files.hpp"
#include "support/input_errors.hpp"
#include "support/test_images.hpp"

namespace lancer {
namespace {

struct DecodedJpeg {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;
  int densityUnit = 0, xDensity = 0, yDensity = 0;
  std::string comment;
};

struct JpegTestError {
  jpeg_error_mgr manager;
  std::jmp_buf jump;
};

void onError(j_common_ptr info) { std::longjmp(reinterpret_cast<JpegTestError*>(info->err)->jump, 1); }

// libjpeg's decoder, with the COM marker kept.
bool decodeJpeg(const std::vector<std::uint8_t>& bytes, DecodedJpeg& out) {
  jpeg_decompress_struct info;
  JpegTestError error{};
  info.err = jpeg_std_error(&error.manager);
  error.manager.error_exit = onError;
  if (setjmp(error.jump)) {
    jpeg_destroy_decompress(&info);
    return false;
  }
  jpeg_create_decompress(&info);
  jpeg_mem_src(&info, bytes.data(), bytes.size());
  jpeg_save_markers(&info, JPEG_COM, 0xffff);
  jpeg_read_header(&info, TRUE);
  info.out_color_space = JCS_RGB;
  jpeg_start_decompress(&info);
  out.width = static_cast<int>(info.output_width);
  out.height = static_cast<int>(info.output_height);
  out.densityUnit = info.density_unit;
  out.xDensity = info.X_density;
  out.yDensity = info.Y_density;
  for (jpeg_saved_marker_ptr marker = info.marker_list; marker != nullptr; marker = marker->next)
    if (marker->marker == JPEG_COM) out.comment.assign(marker->data, marker->data + marker->data_length);
  out.rgb.resize(static_cast<std::size_t>(out.width) * out.height * 3);
  while (info.output_scanline < info.output_height) {
    JSAMPROW row = out.rgb.data() + static_cast<std::size_t>(info.output_scanline) * out.width * 3;
    jpeg_read_scanlines(&info, &row, 1);
  }
  jpeg_finish_decompress(&info);
  jpeg_destroy_decompress(&info);
  return true;
}

ImageMetadata provenance() {
  ImageMetadata metadata;
  metadata.dpi = 300;
  metadata.software = "lancer 9.9.9";
  metadata.command = "lancer render part.msh -o 'a b.jpg' --dpi 300";
  return metadata;
}

TEST(JpegWriter, ComesBackCloseWithDensityAndComment) {
  const test::ScratchFolder folder;
  const Image picture = test::shadedSphere(96, 64, 0.3f);
  ImageWriteOptions options;
  options.metadata = provenance();
  writeImage(folder.file("a.jpg"), picture, options);
  DecodedJpeg decoded;
  ASSERT_TRUE(decodeJpeg(test::readBytes(folder.file("a.jpg")), decoded));
  EXPECT_EQ(decoded.width, 96);
  EXPECT_EQ(decoded.height, 64);
  const test::SampleError error =
      test::sampleError(decoded.rgb, encodeImage8(picture, TransferCurve::Linear, 3));
  EXPECT_LT(error.mean, 2.5);         // quality 90 on a smooth picture
  EXPECT_EQ(decoded.densityUnit, 1);  // dots per inch
  EXPECT_EQ(decoded.xDensity, 300);
  EXPECT_EQ(decoded.yDensity, 300);
  EXPECT_EQ(decoded.comment, "lancer 9.9.9: lancer render part.msh -o 'a b.jpg' --dpi 300");
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"a.jpg"});
}

TEST(JpegWriter, QualityTradesSizeForFidelity) {
  const test::ScratchFolder folder;
  const Image picture = test::shadedSphere(128, 96, 0.6f);
  const std::vector<std::uint8_t> truth = encodeImage8(picture, TransferCurve::Linear, 3);
  double previousError = 1e9;
  std::size_t previousSize = 0;
  for (const int quality : {10, 50, 95}) {
    ImageWriteOptions options;
    options.quality = quality;
    const std::string path = folder.file("q" + std::to_string(quality) + ".jpeg");
    writeImage(path, picture, options);
    const std::vector<std::uint8_t> bytes = test::readBytes(path);
    DecodedJpeg decoded;
    ASSERT_TRUE(decodeJpeg(bytes, decoded));
    const double error = test::sampleError(decoded.rgb, truth).mean;
    EXPECT_LT(error, previousError) << quality;
    EXPECT_GT(bytes.size(), previousSize) << quality;
    previousError = error;
    previousSize = bytes.size();
  }
}

TEST(WebpWriter, LosslessKeepsEverySampleAndAlpha) {
  const test::ScratchFolder folder;
  Image picture = test::shadedSphere(40, 30, 0.1f);
  for (int x = 0; x < 40; ++x) picture.at(x, 0).a = static_cast<float>(x) / 39.0f;  // a ramp of alpha
  ImageWriteOptions options;
  options.lossless = true;
  options.alpha = AlphaChannel::Auto;
  writeImage(folder.file("a.webp"), picture, options);
  const std::vector<std::uint8_t> bytes = test::readBytes(folder.file("a.webp"));
  int width = 0, height = 0;
  std::uint8_t* rgba = WebPDecodeRGBA(bytes.data(), bytes.size(), &width, &height);
  ASSERT_NE(rgba, nullptr);
  const std::vector<std::uint8_t> decoded(rgba, rgba + static_cast<std::size_t>(width) * height * 4);
  WebPFree(rgba);
  EXPECT_EQ(width, 40);
  EXPECT_EQ(height, 30);
  EXPECT_EQ(decoded, encodeImage8(picture, TransferCurve::Linear, 4));
}

TEST(WebpWriter, LossyComesBackCloseWithExif) {
  const test::ScratchFolder folder;
  const Image picture = test::shadedSphere(96, 64, 0.7f);
  ImageWriteOptions options;
  options.metadata = provenance();
  writeImage(folder.file("a.webp"), picture, options);
  const std::vector<std::uint8_t> bytes = test::readBytes(folder.file("a.webp"));
  int width = 0, height = 0;
  std::uint8_t* rgb = WebPDecodeRGB(bytes.data(), bytes.size(), &width, &height);
  ASSERT_NE(rgb, nullptr);
  const std::vector<std::uint8_t> decoded(rgb, rgb + static_cast<std::size_t>(width) * height * 3);
  WebPFree(rgb);
  EXPECT_LT(test::sampleError(decoded, encodeImage8(picture, TransferCurve::Linear, 3)).mean, 2.5);

  const WebPData data{bytes.data(), bytes.size()};
  WebPMux* mux = WebPMuxCreate(&data, 0);
  ASSERT_NE(mux, nullptr);
  WebPData exif{};
  ASSERT_EQ(WebPMuxGetChunk(mux, "EXIF", &exif), WEBP_MUX_OK);
  const std::vector<std::uint8_t> block(exif.bytes, exif.bytes + exif.size);
  WebPMuxDelete(mux);
  EXPECT_EQ(block, exifBlock(provenance()));
}

// TIFF 6.0: "II", 42, the IFD's offset, then sorted 12-byte entries; the rationals say 300/1 inch.
TEST(ExifBlock, HoldsResolutionSoftwareAndDescription) {
  const std::vector<std::uint8_t> block = exifBlock(provenance());
  ASSERT_GT(block.size(), 8u);
  const auto u16 = [&](std::size_t at) { return block[at] | block[at + 1] << 8; };
  const auto u32 = [&](std::size_t at) { return static_cast<std::uint32_t>(u16(at) | u16(at + 2) << 16); };
  EXPECT_EQ(u16(0), 0x4949);
  EXPECT_EQ(u16(2), 42);
  const std::size_t ifd = u32(4);
  ASSERT_EQ(u16(ifd), 5);
  std::vector<int> tags;
  for (std::size_t i = 0; i < 5; ++i) tags.push_back(u16(ifd + 2 + 12 * i));
  EXPECT_EQ(tags, (std::vector<int>{0x010E, 0x011A, 0x011B, 0x0128, 0x0131}));
  const std::size_t xResolution = u32(ifd + 2 + 12 * 1 + 8);
  EXPECT_EQ(static_cast<double>(u32(xResolution)) / u32(xResolution + 4), 300.0);
  EXPECT_EQ(u16(ifd + 2 + 12 * 3 + 8), 2);  // inches
  const std::size_t software = u32(ifd + 2 + 12 * 4 + 8);
  EXPECT_EQ(std::string(reinterpret_cast<const char*>(block.data() + software)), "lancer 9.9.9");
  EXPECT_TRUE(exifBlock(ImageMetadata{}).empty());
}

TEST(JpegWebpBadInput, QualityOutOfRangeWritesNothing) {
  const test::ScratchFolder folder;
  const Image picture = test::shadedSphere(8, 8, 0);
  for (const int quality : {0, 101}) {
    ImageWriteOptions options;
    options.quality = quality;
    for (const char* name : {"a.jpg", "a.webp"})
      EXPECT_EQ(test::messageOf([&] { writeImage(folder.file(name), picture, options); }),
                folder.file(name) + ": error: quality " + std::to_string(quality) +
                    " is out of range: use 1 (smallest file) to 100 (best picture); 90 unless given");
  }
  EXPECT_TRUE(folder.entries().empty());
}

TEST(JpegWebpBadInput, MissingFolderAndOversizeWebp) {
  const test::ScratchFolder folder;
  const std::string path = folder.file("missing/a.jpg");
  EXPECT_EQ(test::messageOf([&] { writeImage(path, test::shadedSphere(8, 8, 0)); }),
            path + ": error: cannot write here: the folder '" + folder.file("missing") + "' does not exist");
  EXPECT_EQ(test::messageOf([&] { requireImageSize("big.webp", ImageFormat::Webp, 20000, 100); }),
            "big.webp: error: 20000x100 is too large for WebP: at most 16383 pixels a side; write a .png");
  EXPECT_NO_THROW(requireImageSize("big.png", ImageFormat::Png, 20000, 100));
  EXPECT_TRUE(folder.entries().empty());
}

TEST(ImageMetadataBadInput, DpiAndQualityChecks) {
  EXPECT_EQ(
      test::messageOf([] { requireDpi(0, SourceLocation{"--dpi"}); }),
      "--dpi: error: 0 is not a resolution in dots per inch: give a number above 0 and at most 65535 (e.g. "
      "300 for print)");
  EXPECT_NE(test::messageOf([] { requireDpi(-72, SourceLocation{"--dpi"}); }), "(no InputError)");
  EXPECT_NE(test::messageOf([] { requireDpi(1e6, SourceLocation{"--dpi"}); }), "(no InputError)");
  EXPECT_NO_THROW(requireDpi(72.5, SourceLocation{"--dpi"}));
  EXPECT_NO_THROW(requireImageQuality(1, SourceLocation{"--quality"}));
  EXPECT_NO_THROW(requireImageQuality(100, SourceLocation{"--quality"}));
  EXPECT_EQ(pixelsPerMetre(300), 11811u);  // 300 / 0.0254 = 11811.02
}

TEST(ImageMetadata, CommandLineQuotesWhatTheShellWould) {
  const char* argv[] = {"lancer", "render", "my part.msh", "-o", "it's.png", "--dpi", "300"};
  EXPECT_EQ(quoteCommandLine(7, argv), "lancer render 'my part.msh' -o 'it'\\''s.png' --dpi 300");
}

}  // namespace
}  // namespace lancer
