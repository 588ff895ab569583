// Part files of `lancer render --shard I/N`: band items cut the image the same way for every task,
// parts assembled give exactly the file writeImage writes for the whole image (streamed PNG, BMP,
// PPM; GIF whole), and missing, doubled, foreign or truncated parts are refused by name.
#include "lancer/cluster/tile_parts.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include "support/files.hpp"
#include "support/input_errors.hpp"

namespace lancer {
namespace {

// A picture whose every pixel differs, partly transparent.
Image gradient(int width, int height) {
  Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      image.at(x, y) =
          Rgba{static_cast<float>(x) / static_cast<float>(width),
               static_cast<float>(y) / static_cast<float>(height), 0.3f, (x + y) % 3 ? 1.0f : 0.5f};
  return image;
}

// Writes the parts of `image` as `count` tasks would, beside `output`; returns their paths.
std::vector<std::string> writeParts(const Image& image, const std::string& output, int count, bool alpha) {
  std::vector<std::string> paths;
  for (int index = 0; index < count; ++index) {
    TilePartHeader header;
    header.width = image.width();
    header.height = image.height();
    header.shard = Shard{index, count};
    header.bandsPerItem = bandItems(image.width(), image.height(), count).bandsPerItem;
    header.curve = TransferCurve::Srgb;
    header.alpha = alpha;
    const BandItems items = bandItemsOf(image.height(), header.bandsPerItem);
    paths.push_back(tilePartPath(output, header.shard));
    TilePartWriter part(paths.back(), header);
    for (const int item : tilePartItems(header)) {
      const BandRange range = items.item(item);
      const int y0 = range.first * kTileSize;
      const int y1 = std::min(image.height(), (range.first + range.count) * kTileSize);
      part.writeItem(image.crop(0, y0, image.width(), y1 - y0));
    }
    part.commit();
  }
  return paths;
}

TEST(BandItems, CoverEveryBandOnceWithAtLeastTwoItemsPerWorkerWhereTheyCan) {
  for (const auto& [width, height, workers] :
       {std::tuple{64, 48, 2}, {3000, 2000, 3}, {500, 4000, 16}, {40, 33, 5}}) {
    const BandItems items = bandItems(width, height, workers);
    EXPECT_EQ(items.bands, (height + 31) / 32);
    int next = 0;
    for (int i = 0; i < items.itemCount; ++i) {
      EXPECT_EQ(items.item(i).first, next);
      next += items.item(i).count;
    }
    EXPECT_EQ(next, items.bands);
    if (items.bands >= 2 * workers) {
      EXPECT_GE(items.itemCount, 2 * workers) << width << "x" << height;
    }
  }
}

TEST(TileParts, AssembledPartsAreTheFileOfTheWholeImage) {
  const test::ScratchFolder folder;
  const Image image = gradient(90, 333);  // 11 bands, the last one short
  for (const char* name : {"w.png", "w.bmp", "w.ppm", "w.gif"}) {
    SCOPED_TRACE(name);
    const bool alpha = std::string(name) == "w.png";
    ImageWriteOptions options;
    options.curve = TransferCurve::Srgb;
    options.alpha = alpha ? AlphaChannel::Always : AlphaChannel::Never;
    writeImage(folder.file(std::string("whole-") + name), image, options);
    for (const int count : {1, 3, 4}) {
      const std::vector<std::string> parts = writeParts(image, folder.file(name), count, alpha);
      assembleTileParts({parts.rbegin(), parts.rend()}, folder.file(name));  // any order
      EXPECT_EQ(test::readBytes(folder.file(name)),
                test::readBytes(folder.file(std::string("whole-") + name)))
          << count << " parts";
      for (const std::string& part : parts) std::filesystem::remove(part);
    }
  }
}

TEST(TileParts, MissingDoubledForeignAndTruncatedPartsAreRefusedByName) {
  const test::ScratchFolder folder;
  const std::vector<std::string> parts = writeParts(gradient(64, 200), folder.file("p.png"), 3, false);
  EXPECT_EQ(test::messageOf([&] {
              assembleTileParts({parts[0], parts[2]}, folder.file("p.png"));
            }),
            folder.file("p.png") + ": error: part 1 of 3 is missing (expected a file like " +
                folder.file("p.png") + ".part-1-of-3); render it with --shard 1/3");
  EXPECT_NE(test::messageOf([&] {
              assembleTileParts({parts[0], parts[0], parts[1]}, folder.file("p.png"));
            }).find("part 0 of 3 is given twice"),
            std::string::npos);
  const std::vector<std::string> other = writeParts(gradient(64, 100), folder.file("q.png"), 3, false);
  EXPECT_NE(test::messageOf([&] {
              assembleTileParts({parts[0], parts[1], other[2]}, folder.file("p.png"));
            }).find("is not from the same render as"),
            std::string::npos);
  std::vector<std::uint8_t> bytes = test::readBytes(parts[1]);
  bytes.resize(bytes.size() - 16);
  test::writeBytes(parts[1], bytes);
  EXPECT_NE(test::messageOf([&] { assembleTileParts(parts, folder.file("p.png")); }).find("or truncated?"),
            std::string::npos);
  folder.write("junk.part", "not a part");
  EXPECT_EQ(test::messageOf([&] { TilePartReader reader(folder.file("junk.part")); }),
            folder.file("junk.part") +
                ":@0: error: not a lancer part file (written by `lancer render --shard I/N`)");
  EXPECT_FALSE(std::filesystem::exists(folder.file("p.png")));
}

}  // namespace
}  // namespace lancer
