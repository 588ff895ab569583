// A still image cut into work items for a cluster: each item is a run of consecutive bands (rows of
// 32-pixel tiles), large enough to keep a rank's threads busy, small enough that every rank gets some.
#pragma once

#include "lancer/render/renderer.hpp"

namespace lancer {

struct BandItems {
  int bands = 0;         // of the whole image
  int bandsPerItem = 1;  // every item but the last has this many
  int itemCount = 0;

  BandRange item(int index) const;
};

// Items for an image of width x height shared by `workers` ranks or tasks: about kTilesPerItem tiles
// each, but at least two items per worker where the image has enough bands. Depends only on its
// arguments, so every task of a job array cuts the image the same way.
BandItems bandItems(int width, int height, int workers);

// Items of `bandsPerItem` bands (as a part file records them).
BandItems bandItemsOf(int height, int bandsPerItem);

}  // namespace lancer
