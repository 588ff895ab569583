// What a PNG (and an EXR) says about itself: the DPI in pHYs, lancer's version and the command in text
// chunks, read back by walking the file's chunks; a file without metadata has none of them.
#include <gtest/gtest.h>

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "lancer/image/exr_io.hpp"
#include "lancer/image/image_io.hpp"
#include "lancer/image/image_row_writer.hpp"
#include "support/files.hpp"
#include "support/test_images.hpp"

#if LANCER_TEST_OPENEXR
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfStandardAttributes.h>
#include <ImfStringAttribute.h>
#endif

namespace lancer {
namespace {

struct PngChunk {
  std::string type;
  std::vector<std::uint8_t> data;
};

// PNG 1.2 section 3.2: length (big-endian), type, data, CRC, after the 8-byte signature.
std::vector<PngChunk> pngChunks(const std::vector<std::uint8_t>& bytes) {
  std::vector<PngChunk> chunks;
  std::size_t at = 8;
  while (at + 12 <= bytes.size()) {
    const std::uint32_t length = static_cast<std::uint32_t>(bytes[at] << 24 | bytes[at + 1] << 16 |
                                                            bytes[at + 2] << 8 | bytes[at + 3]);
    PngChunk chunk;
    chunk.type.assign(bytes.begin() + static_cast<std::ptrdiff_t>(at + 4),
                      bytes.begin() + static_cast<std::ptrdiff_t>(at + 8));
    chunk.data.assign(bytes.begin() + static_cast<std::ptrdiff_t>(at + 8),
                      bytes.begin() + static_cast<std::ptrdiff_t>(at + 8 + length));
    chunks.push_back(chunk);
    at += 12 + length;
  }
  return chunks;
}

// The tEXt keywords and texts, and the iTXt ones (uncompressed, no language).
std::map<std::string, std::string> pngTexts(const std::vector<PngChunk>& chunks) {
  std::map<std::string, std::string> texts;
  for (const PngChunk& chunk : chunks) {
    const std::string data(chunk.data.begin(), chunk.data.end());
    const std::size_t zero = data.find('\0');
    if (chunk.type == "tEXt") texts[data.substr(0, zero)] = data.substr(zero + 1);
    if (chunk.type == "iTXt") {
      // keyword \0 compression-flag compression-method language \0 translated-keyword \0 text
      const std::size_t language = zero + 3;
      const std::size_t translated = data.find('\0', language) + 1;
      texts[data.substr(0, zero)] = data.substr(data.find('\0', translated) + 1);
    }
  }
  return texts;
}

ImageMetadata metadata(const std::string& command) {
  ImageMetadata m;
  m.dpi = 300;
  m.software = "lancer 9.9.9";
  m.command = command;
  return m;
}

std::vector<std::string> types(const std::vector<PngChunk>& chunks) {
  std::vector<std::string> names;
  for (const PngChunk& chunk : chunks) names.push_back(chunk.type);
  return names;
}

TEST(PngMetadata, PhysAndTextBeforeThePixels) {
  const test::ScratchFolder folder;
  ImageWriteOptions options;
  options.curve = TransferCurve::Srgb;
  options.metadata = metadata("lancer render part.msh --dpi 300 -o a.png");
  const Image picture = test::shadedSphere(16, 12, 0.5f);
  writeImage(folder.file("a.png"), picture, options);
  const std::vector<PngChunk> chunks = pngChunks(test::readBytes(folder.file("a.png")));
  const std::vector<std::string> names = types(chunks);
  ASSERT_EQ(names.front(), "IHDR");
  ASSERT_EQ(names.back(), "IEND");
  std::size_t phys = 0, idat = 0;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (names[i] == "pHYs") phys = i;
    if (names[i] == "IDAT" && idat == 0) idat = i;
  }
  ASSERT_GT(phys, 0u);
  EXPECT_LT(phys, idat);  // PNG 1.2: pHYs must precede the first IDAT
  // 11811 pixels per metre both ways, unit 1 (the metre).
  EXPECT_EQ(chunks[phys].data, (std::vector<std::uint8_t>{0, 0, 0x2e, 0x23, 0, 0, 0x2e, 0x23, 1}));
  const std::map<std::string, std::string> texts = pngTexts(chunks);
  EXPECT_EQ(texts.at("Software"), "lancer 9.9.9");
  EXPECT_EQ(texts.at("Comment"), "lancer render part.msh --dpi 300 -o a.png");
  // The pixels are those of a file without metadata.
  EXPECT_EQ(test::differingPixels(readPng(folder.file("a.png")), readPng(folder.file("a.png"))), 0);
  ImageWriteOptions plain;
  plain.curve = TransferCurve::Srgb;
  writeImage(folder.file("plain.png"), picture, plain);
  EXPECT_EQ(test::differingPixels(readPng(folder.file("a.png")), readPng(folder.file("plain.png"))), 0);
}

TEST(PngMetadata, NoneWithoutMetadata) {
  const test::ScratchFolder folder;
  writeImage(folder.file("a.png"), test::shadedSphere(8, 8, 0));
  for (const std::string& name : types(pngChunks(test::readBytes(folder.file("a.png")))))
    EXPECT_TRUE(name != "pHYs" && name != "tEXt" && name != "iTXt") << name;
}

TEST(PngMetadata, Utf8CommandGoesToItxt) {
  const test::ScratchFolder folder;
  ImageWriteOptions options;
  options.metadata = metadata("lancer render pièce.msh -o a.png");
  writeImage(folder.file("a.png"), test::shadedSphere(8, 8, 0), options);
  const std::vector<PngChunk> chunks = pngChunks(test::readBytes(folder.file("a.png")));
  EXPECT_EQ(pngTexts(chunks).at("Comment"), "lancer render pièce.msh -o a.png");
  bool itxt = false;
  for (const PngChunk& chunk : chunks) itxt = itxt || chunk.type == "iTXt";
  EXPECT_TRUE(itxt);
}

// The band-by-band writer gives the whole-image writer's bytes, metadata included.
TEST(PngMetadata, RowWriterWritesTheSameChunks) {
  const test::ScratchFolder folder;
  ImageWriteOptions options;
  options.alpha = AlphaChannel::Never;
  options.metadata = metadata("lancer render x.msh");
  const Image picture = test::shadedSphere(20, 10, 0.2f);
  writeImage(folder.file("whole.png"), picture, options);
  ImageRowWriter rows(folder.file("rows.png"), 20, 10, options);
  rows.writeRows(picture);
  rows.commit();
  test::expectSameFile(folder.file("rows.png"), folder.file("whole.png"));
}

#if LANCER_TEST_OPENEXR
TEST(ExrMetadata, HeaderAttributes) {
  const test::ScratchFolder folder;
  ImageWriteOptions options;
  options.metadata = metadata("lancer render x.msh -o a.exr");
  writeImage(folder.file("a.exr"), test::shadedSphere(8, 8, 0), options);
  Imf::InputFile in(folder.file("a.exr").c_str());
  ASSERT_TRUE(Imf::hasComments(in.header()));
  EXPECT_EQ(Imf::comments(in.header()), "lancer render x.msh -o a.exr");
  EXPECT_EQ(in.header().typedAttribute<Imf::StringAttribute>("software").value(), "lancer 9.9.9");
  EXPECT_FLOAT_EQ(Imf::xDensity(in.header()), 300.0f);
}
#endif

}  // namespace
}  // namespace lancer
