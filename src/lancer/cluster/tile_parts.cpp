#include "lancer/cluster/tile_parts.hpp"

#include <fmt/format.h>

#include <array>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>

#include "lancer/image/image_row_writer.hpp"
#include "lancer/util/input_error.hpp"

namespace lancer {
namespace {

constexpr std::array<char, 12> kMagic = {'L', 'A', 'N', 'C', 'E', 'R', 'P', 'A', 'R', 'T', '1', '\n'};
// Written as the machine stores it: a part read on a machine of the other byte order is refused.
constexpr std::uint32_t kByteOrderMark = 0x01020304;
constexpr int kHeaderFields = 8;
constexpr std::uint64_t kHeaderBytes = sizeof kMagic + sizeof(std::int32_t) * kHeaderFields;

std::uint64_t itemBytes(const TilePartHeader& header, int item) {
  const BandRange range = bandItemsOf(header.height, header.bandsPerItem).item(item);
  const int y0 = range.first * kTileSize;
  const int y1 = std::min(header.height, (range.first + range.count) * kTileSize);
  return static_cast<std::uint64_t>(header.width) * static_cast<std::uint64_t>(y1 - y0) * sizeof(Rgba);
}

}  // namespace

std::string tilePartPath(const std::string& imagePath, const Shard& shard) {
  return fmt::format("{}.part-{}-of-{}", imagePath, shard.index, shard.count);
}

std::vector<int> tilePartItems(const TilePartHeader& header) {
  std::vector<int> items;
  const int count = bandItemsOf(header.height, header.bandsPerItem).itemCount;
  for (int i = header.shard.index; i < count; i += header.shard.count) items.push_back(i);
  return items;
}

TilePartWriter::TilePartWriter(const std::string& path, const TilePartHeader& header) : file_(path) {
  const std::array<std::int32_t, kHeaderFields> fields = {static_cast<std::int32_t>(kByteOrderMark),
                                                          header.width,
                                                          header.height,
                                                          header.shard.index,
                                                          header.shard.count,
                                                          header.bandsPerItem,
                                                          header.curve == TransferCurve::Srgb ? 1 : 0,
                                                          header.alpha ? 1 : 0};
  file_.write(kMagic.data(), kMagic.size());
  file_.write(fields.data(), sizeof fields);
  file_.throwIfFailed();
}

void TilePartWriter::writeItem(const Image& rows) {
  file_.write(rows.pixels().data(), rows.pixels().size_bytes());
  file_.throwIfFailed();
}

void TilePartWriter::commit() { file_.commit(); }

struct TilePartReader::Stream {
  std::FILE* file = nullptr;
  ~Stream() {
    if (file != nullptr) std::fclose(file);
  }
};

TilePartReader::TilePartReader(const std::string& path) : path_(path), stream_(std::make_unique<Stream>()) {
  stream_->file = std::fopen(path.c_str(), "rb");
  if (stream_->file == nullptr)
    throw InputError(SourceLocation{path}, fmt::format("cannot open the part: {}", std::strerror(errno)));
  std::array<char, kMagic.size()> magic{};
  std::array<std::int32_t, kHeaderFields> fields{};
  if (std::fread(magic.data(), 1, magic.size(), stream_->file) != magic.size() || magic != kMagic ||
      std::fread(fields.data(), sizeof fields, 1, stream_->file) != 1)
    throw InputError(SourceLocation{path, 0, 0, 0},
                     "not a lancer part file (written by `lancer render --shard I/N`)");
  if (static_cast<std::uint32_t>(fields[0]) != kByteOrderMark)
    throw InputError(SourceLocation{path, 0, 0, 0},
                     "this part was written on a machine of the other byte order; assemble it there");
  header_.width = fields[1];
  header_.height = fields[2];
  header_.shard = Shard{fields[3], fields[4]};
  header_.bandsPerItem = fields[5];
  header_.curve = fields[6] == 1 ? TransferCurve::Srgb : TransferCurve::Linear;
  header_.alpha = fields[7] == 1;
  if (header_.width < 1 || header_.width > kMaxImageSide || header_.height < 1 ||
      header_.height > kMaxImageSide || header_.shard.count < 1 || header_.shard.index < 0 ||
      header_.shard.index >= header_.shard.count || header_.bandsPerItem < 1)
    throw InputError(SourceLocation{path, 0, 0, sizeof kMagic},
                     "the part's header is damaged (size, shard or band counts out of range)");
  items_ = tilePartItems(header_);
  std::uint64_t expected = kHeaderBytes;
  for (const int item : items_) expected += itemBytes(header_, item);
  std::error_code error;
  const std::uint64_t size = std::filesystem::file_size(path, error);
  if (error || size != expected)
    throw InputError(SourceLocation{path},
                     fmt::format("the part holds {} bytes, but {} items of a {}x{} image need {}; was it "
                                 "written by a different render, or truncated?",
                                 error ? 0 : size, items_.size(), header_.width, header_.height, expected));
}

TilePartReader::~TilePartReader() = default;

Image TilePartReader::readItem() {
  if (next_ >= items_.size()) throw InputError(SourceLocation{path_}, "read past the part's last item");
  const int item = items_[next_++];
  const BandRange range = bandItemsOf(header_.height, header_.bandsPerItem).item(item);
  const int y0 = range.first * kTileSize;
  Image rows(header_.width, std::min(header_.height, (range.first + range.count) * kTileSize) - y0);
  if (std::fread(rows.pixels().data(), 1, rows.pixels().size_bytes(), stream_->file) !=
      rows.pixels().size_bytes())
    throw InputError(SourceLocation{path_},
                     fmt::format("cannot read item {}: {}", item, std::strerror(errno)));
  return rows;
}

void assembleTileParts(const std::vector<std::string>& parts, const std::string& output,
                       const ImageMetadata& metadata) {
  if (parts.empty()) throw InputError(SourceLocation{output}, "no part files to assemble");
  std::map<int, std::unique_ptr<TilePartReader>> readers;  // by shard index
  std::string firstPath;
  for (const std::string& path : parts) {
    auto reader = std::make_unique<TilePartReader>(path);
    const TilePartHeader& h = reader->header();
    if (firstPath.empty()) {
      firstPath = path;
    } else {
      const TilePartHeader& first = readers.begin()->second->header();
      if (h.width != first.width || h.height != first.height || h.shard.count != first.shard.count ||
          h.bandsPerItem != first.bandsPerItem || h.curve != first.curve || h.alpha != first.alpha)
        throw InputError(SourceLocation{path},
                         fmt::format("this part ({}x{}, one of {}) is not from the same render as {} ({}x{}, "
                                     "one of {})",
                                     h.width, h.height, h.shard.count, firstPath, first.width, first.height,
                                     first.shard.count));
    }
    if (readers.count(h.shard.index) != 0)
      throw InputError(SourceLocation{path},
                       fmt::format("part {} of {} is given twice", h.shard.index, h.shard.count));
    readers.emplace(h.shard.index, std::move(reader));
  }
  const TilePartHeader header = readers.begin()->second->header();
  for (int i = 0; i < header.shard.count; ++i)
    if (readers.count(i) == 0)
      throw InputError(SourceLocation{output},
                       fmt::format("part {} of {} is missing (expected a file like {}); render it with "
                                   "--shard {}/{}",
                                   i, header.shard.count, tilePartPath(output, Shard{i, header.shard.count}),
                                   i, header.shard.count));

  ImageWriteOptions options;
  options.curve = header.curve;
  options.alpha = header.alpha ? AlphaChannel::Always : AlphaChannel::Never;
  options.metadata = metadata;
  const int itemCount = bandItemsOf(header.height, header.bandsPerItem).itemCount;
  const auto nextItem = [&](int item) { return readers.at(item % header.shard.count)->readItem(); };
  if (!ImageRowWriter::streams(imageFormatFromPath(output))) {
    Image image(header.width, header.height);
    for (int item = 0, y = 0; item < itemCount; ++item) {
      const Image rows = nextItem(item);
      image.pasteTile(rows, 0, y);
      y += rows.height();
    }
    writeImage(output, image, options);
    return;
  }
  ImageRowWriter writer(output, header.width, header.height, options);
  for (int item = 0; item < itemCount; ++item) writer.writeRows(nextItem(item));
  writer.commit();
}

}  // namespace lancer
