// Part files of a still rendered as a job array (`lancer render --shard I/N`): task I stores the
// band items i with i % N == I, as linear float RGBA exactly as the renderer made them, so that
// `lancer assemble --tiles` writes the same bytes as a single `lancer render` would.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "lancer/cluster/band_items.hpp"
#include "lancer/cluster/shard.hpp"
#include "lancer/image/atomic_file.hpp"
#include "lancer/image/image.hpp"
#include "lancer/image/image_io.hpp"

namespace lancer {

// What every part of one image records, and assemble checks they agree on.
struct TilePartHeader {
  int width = 0, height = 0;
  Shard shard;
  int bandsPerItem = 1;
  TransferCurve curve = TransferCurve::Linear;
  bool alpha = false;  // AlphaChannel::Always; else Never
};

// "poster.png.part-3-of-16": the part of task I of N beside the image it belongs to.
std::string tilePartPath(const std::string& imagePath, const Shard& shard);

// The band items the part of `header.shard` holds, in the order it stores them.
std::vector<int> tilePartItems(const TilePartHeader& header);

// Writes the header now (a bad folder fails before rendering), then the items in order; commit()
// publishes the part atomically.
class TilePartWriter {
 public:
  TilePartWriter(const std::string& path, const TilePartHeader& header);
  void writeItem(const Image& rows);
  void commit();

 private:
  AtomicFileWriter file_;
};

// Reads one part's items in order, checking its header and size first. InputError naming the file.
class TilePartReader {
 public:
  explicit TilePartReader(const std::string& path);
  ~TilePartReader();
  TilePartReader(const TilePartReader&) = delete;
  TilePartReader& operator=(const TilePartReader&) = delete;

  const TilePartHeader& header() const { return header_; }
  // The next item's rows (the part's items come in tilePartItems order).
  Image readItem();

 private:
  std::string path_;
  TilePartHeader header_;
  std::vector<int> items_;
  std::size_t next_ = 0;
  struct Stream;
  std::unique_ptr<Stream> stream_;
};

// Stitches the parts into `output` (PNG, BMP or PPM streamed band by band; a GIF whole). Every part
// 0..N-1 must be among `parts` once, all from the same image; InputError naming what is missing or
// does not match. `metadata`: what the file records of how it was made (image_metadata.hpp).
void assembleTileParts(const std::vector<std::string>& parts, const std::string& output,
                       const ImageMetadata& metadata = {});

}  // namespace lancer
