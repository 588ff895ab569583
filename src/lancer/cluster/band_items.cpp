#include "lancer/cluster/band_items.hpp"

#include <algorithm>

namespace lancer {
namespace {

// Enough tiles that 16 threads have four each before the item's last band holds them up.
constexpr int kTilesPerItem = 64;

}  // namespace

BandRange BandItems::item(int index) const {
  const int first = index * bandsPerItem;
  return BandRange{first, std::min(bandsPerItem, bands - first)};
}

BandItems bandItemsOf(int height, int bandsPerItem) {
  BandItems items;
  items.bands = bandCountOf(height);
  items.bandsPerItem = std::max(1, bandsPerItem);
  items.itemCount = (items.bands + items.bandsPerItem - 1) / items.bandsPerItem;
  return items;
}

BandItems bandItems(int width, int height, int workers) {
  const int tilesX = (width + kTileSize - 1) / kTileSize;
  const int bands = bandCountOf(height);
  const int forThreads = (kTilesPerItem + tilesX - 1) / tilesX;
  const int forWorkers = std::max(1, bands / (2 * std::max(1, workers)));
  return bandItemsOf(height, std::min(forThreads, forWorkers));
}

}  // namespace lancer
