// Golden images of element edges: gmsh's unit square (tests/data/geo/square.geo) as 8-node quads and
// as 6-node triangles in perspective over a grey floor; the edges made by splitting second-order
// elements must not show. Regenerate with scripts/update_golden.sh.
#include <gtest/gtest.h>

#include <string>

#include "lancer/scene/scene_loader.hpp"
#include "support/files.hpp"
#include "support/golden.hpp"
#include "support/test_scenes.hpp"

namespace lancer {
namespace {

TEST(EdgesGolden, QuadAndSecondOrderMeshesInPerspective) {
  for (const char* scene : {"edges_quad8.toml", "edges_tri6.toml"}) {
    const Image image = test::renderScene(loadScene(test::dataFile(std::string("render/") + scene)));
    test::expectImageNear(image, test::dataFile("render/golden/" + std::string(scene) + ".png"),
                          test::kRenderGoldenMinPsnrDb);
  }
}

}  // namespace
}  // namespace lancer
