// renderBands: bands of 32 rows reach the sink in order, hold the same pixels as renderImage for any
// thread count, stay within a few bands of memory for a tall image, and streamed to an ImageRowWriter
// give the same file as rendering the whole image and writing it.
#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <string>
#include <vector>

#include "lancer/image/image_row_writer.hpp"
#include "lancer/scene/scene_loader.hpp"
#include "support/files.hpp"
#include "support/test_scenes.hpp"

namespace lancer {
namespace {

// Two squares at different heights under a light, seen in perspective: shading, a shadow and, with
// a transparent background, partly covered pixels.
SceneDescription twoSquares(int width, int height, bool transparent) {
  SceneDescription d;
  d.render.width = width;
  d.render.height = height;
  d.render.samples = 4;
  d.render.transparentBackground = transparent;
  d.camera.projection = Projection::Perspective;
  d.camera.position = Vec3d{0.5, -3, 4};
  d.camera.lookAt = Vec3d{0, 0, 0};
  d.lights = {{Vec3d{1, -1, 5}, {1, 1, 1}, {1, 0, 0}}};
  Material matte = defaultMaterial();
  matte.kd = {0.6f, 0.4f, 0.3f};
  d.materials = {matte};
  d.meshes.resize(2);
  return d;
}

struct Rendering {
  SceneDescription description;
  Scene scene;
  Accelerator accelerator;
  Camera camera;

  explicit Rendering(const SceneDescription& d)
      : description(d),
        scene(test::sceneFromMeshes(d, {test::squareMesh(-1.5f, -1.5f, 1.5f, 1.5f, 0),
                                        test::squareMesh(-0.3f, -0.4f, 0.2f, 0.3f, 0.6f)})),
        accelerator(Accelerator::build(scene.geometry.positions, scene.geometry.faces, AccelKind::KdTreeSah)),
        camera(d.camera, scene.geometry.origin, scene.geometry.bounds, d.render.width, d.render.height) {}

  Image whole(int threads) const {
    RenderOptions options;
    options.threads = threads;
    return Renderer(scene, accelerator, camera, description.render).renderImage(options);
  }
  RenderStats bands(int threads, const BandSink& sink, const std::atomic<bool>* cancel = nullptr) const {
    RenderOptions options;
    options.threads = threads;
    options.cancel = cancel;
    RenderStats stats;
    Renderer(scene, accelerator, camera, description.render).renderBands(options, sink, &stats);
    return stats;
  }
};

TEST(BandRender, BandsComeInOrderAndMatchTheWholeImageForAnyThreadCount) {
  const Rendering r(twoSquares(77, 45, false));
  const Image expected = r.whole(1);
  // Both bands show the squares: the comparison is of a picture, not of background.
  const Rgba background = expected.at(0, 0);
  EXPECT_NE(expected.at(38, 20), background);
  EXPECT_NE(expected.at(38, 40), background);
  for (int threads : {1, 2, 3}) {
    SCOPED_TRACE(threads);
    std::vector<int> starts, heights;
    Image assembled(77, 45, Rgba{9, 9, 9, 9});
    const RenderStats stats = r.bands(threads, [&](int y0, const Image& band) {
      starts.push_back(y0);
      heights.push_back(band.height());
      ASSERT_EQ(band.width(), 77);
      assembled.pasteTile(band, 0, y0);
    });
    EXPECT_EQ(starts, (std::vector<int>{0, 32}));
    EXPECT_EQ(heights, (std::vector<int>{32, 13}));
    EXPECT_TRUE(assembled == expected);
    EXPECT_FALSE(stats.cancelled);
  }
}

TEST(BandRender, TallImageBuffersAFewBandsNotTheImage) {
  // 2000 rows are 63 bands; the sink checks that it is never more than the window behind.
  const Rendering r(twoSquares(40, 2000, false));
  for (int threads : {1, 3}) {
    SCOPED_TRACE(threads);
    int nextRow = 0;
    const RenderStats stats = r.bands(threads, [&](int y0, const Image& band) {
      EXPECT_EQ(y0, nextRow);
      nextRow += band.height();
    });
    EXPECT_EQ(nextRow, 2000);
    const int window = bandWindow(40, threads);
    EXPECT_LE(window, 8);
    EXPECT_GE(stats.peakBufferedRows, kTileSize);
    EXPECT_LE(stats.peakBufferedRows, window * kTileSize);
    EXPECT_LE(bandMemoryBytes(40, 2000, threads), std::uint64_t{8} * kTileSize * 40 * sizeof(Rgba));
  }
}

class StreamedFile : public testing::TestWithParam<std::string> {};

// The pipeline of `lancer render -o FILE`: bands straight into the file's rows.
TEST_P(StreamedFile, EqualsTheWholeImageWrittenAtOnce) {
  const std::string extension = GetParam();
  test::ScratchFolder folder;
  for (bool transparent : {false, true}) {
    const Rendering r(twoSquares(77, 45, transparent));
    ImageWriteOptions options;
    options.alpha = transparent ? AlphaChannel::Always : AlphaChannel::Never;
    options.curve = transparent ? TransferCurve::Srgb : TransferCurve::Linear;
    writeImage(folder.file("whole" + extension), r.whole(2), options);
    for (int threads : {1, 3}) {
      SCOPED_TRACE(std::to_string(threads) + (transparent ? " transparent" : " opaque"));
      const std::string path = folder.file("streamed" + extension);
      ImageRowWriter writer(path, 77, 45, options);
      r.bands(threads, [&](int, const Image& band) { writer.writeRows(band); });
      writer.commit();
      EXPECT_EQ(test::readBytes(path), test::readBytes(folder.file("whole" + extension)));
    }
  }
}

INSTANTIATE_TEST_SUITE_P(EveryFormat, StreamedFile, testing::Values(".png", ".bmp", ".ppm"),
                         [](const testing::TestParamInfo<std::string>& param) {
                           return param.param.substr(1);
                         });

TEST(BandRender, CancelStopsTheBandsAndTheOldFileStays) {
  test::ScratchFolder folder;
  const std::string path = folder.file("out.png");
  const std::vector<std::uint8_t> old = {'o', 'l', 'd'};
  test::writeBytes(path, old);
  const Rendering r(twoSquares(40, 2000, false));
  std::atomic<bool> cancel{false};
  int bands = 0;
  RenderStats stats;
  {
    ImageWriteOptions options;
    options.alpha = AlphaChannel::Never;
    ImageRowWriter writer(path, 40, 2000, options);
    stats = r.bands(
        2,
        [&](int, const Image& band) {
          writer.writeRows(band);
          if (++bands == 2) cancel = true;  // as Ctrl-C while the render runs
        },
        &cancel);
    // The caller sees the cancel and does not commit: the writer's destructor removes its file.
  }
  EXPECT_TRUE(stats.cancelled);
  EXPECT_EQ(bands, 2);
  test::expectOnlyFile(folder, "out.png", old);
}

TEST(BandRender, AnExceptionFromTheSinkStopsTheWorkersAndPropagates) {
  const Rendering r(twoSquares(40, 2000, false));
  int bands = 0;
  EXPECT_THROW(r.bands(3,
                       [&](int, const Image&) {
                         if (++bands == 3) throw std::runtime_error("disk full");
                       }),
               std::runtime_error);
  EXPECT_EQ(bands, 3);
}

TEST(BandRender, RowsOfABandRangeAreThoseOfTheWholeImage) {
  // A cluster's work item: bands [first, first + count) alone give the same pixels as the whole image.
  const Rendering r(twoSquares(70, 140, true));
  const Image expected = r.whole(2);
  const Renderer renderer(r.scene, r.accelerator, r.camera, r.description.render);
  ASSERT_EQ(bandCountOf(140), 5);
  RenderOptions options;
  options.threads = 3;
  for (const BandRange range : {BandRange{0, 1}, BandRange{1, 3}, BandRange{4, 1}, BandRange{3, -1}}) {
    SCOPED_TRACE(range.first);
    const Image rows = renderer.renderRows(range, options);
    const int y0 = range.first * kTileSize;
    const int y1 = range.count < 0 ? 140 : std::min(140, (range.first + range.count) * kTileSize);
    EXPECT_EQ(rows, expected.crop(0, y0, 70, y1 - y0));
  }
}

}  // namespace
}  // namespace lancer
