#include "support/gif_decoder.hpp"

#include <gif_lib.h>
#include <gtest/gtest.h>

namespace lancer::test {
namespace {

std::optional<int> netscapeLoop(const ExtensionBlock* blocks, int count) {
  for (int i = 0; i + 1 < count; ++i) {
    if (blocks[i].Function == APPLICATION_EXT_FUNC_CODE && blocks[i].ByteCount == 11 &&
        std::string(reinterpret_cast<const char*>(blocks[i].Bytes), 11) == "NETSCAPE2.0" &&
        blocks[i + 1].Function == CONTINUE_EXT_FUNC_CODE && blocks[i + 1].ByteCount == 3 &&
        blocks[i + 1].Bytes[0] == 1) {
      return blocks[i + 1].Bytes[1] | (blocks[i + 1].Bytes[2] << 8);
    }
  }
  return std::nullopt;
}

}  // namespace

DecodedGif decodeGif(const std::string& path) {
  DecodedGif out;
  int error = 0;
  GifFileType* gif = DGifOpenFileName(path.c_str(), &error);
  if (gif == nullptr) {
    out.error = GifErrorString(error);
    return out;
  }
  if (DGifSlurp(gif) == GIF_ERROR) {
    out.error = GifErrorString(gif->Error);
    DGifCloseFile(gif, &error);
    return out;
  }
  out.width = gif->SWidth;
  out.height = gif->SHeight;
  out.globalPalette = gif->SColorMap != nullptr;
  if (gif->ImageCount > 0) {
    out.loopCount =
        netscapeLoop(gif->SavedImages[0].ExtensionBlocks, gif->SavedImages[0].ExtensionBlockCount);
  }
  std::vector<std::uint8_t> canvas(static_cast<std::size_t>(out.width) * out.height * 3, 0);
  for (int i = 0; i < gif->ImageCount; ++i) {
    const SavedImage& image = gif->SavedImages[i];
    DecodedGifFrame frame;
    GraphicsControlBlock control;
    if (DGifSavedExtensionToGCB(gif, i, &control) == GIF_OK) frame.delay = control.DelayTime;
    frame.left = image.ImageDesc.Left;
    frame.top = image.ImageDesc.Top;
    frame.width = image.ImageDesc.Width;
    frame.height = image.ImageDesc.Height;
    frame.localPalette = image.ImageDesc.ColorMap != nullptr;
    const ColorMapObject* map =
        image.ImageDesc.ColorMap != nullptr ? image.ImageDesc.ColorMap : gif->SColorMap;
    for (int y = 0; y < frame.height; ++y) {
      for (int x = 0; x < frame.width; ++x) {
        const GifByteType index = image.RasterBits[y * frame.width + x];
        const GifColorType colour = map->Colors[index];
        const std::size_t at = (static_cast<std::size_t>(frame.top + y) * out.width + frame.left + x) * 3;
        canvas[at] = colour.Red;
        canvas[at + 1] = colour.Green;
        canvas[at + 2] = colour.Blue;
      }
    }
    frame.canvas = canvas;
    out.frames.push_back(std::move(frame));
  }
  DGifCloseFile(gif, &error);
  return out;
}

void expectGifLayout(const DecodedGif& gif, const GifLayout& layout) {
  ASSERT_EQ(gif.error, "");
  EXPECT_EQ(gif.width, layout.width);
  EXPECT_EQ(gif.height, layout.height);
  EXPECT_EQ(gif.globalPalette, layout.globalPalette);
  EXPECT_EQ(gif.loopCount, layout.loopCount);
  ASSERT_EQ(gif.frames.size(), layout.frames);
  for (std::size_t k = 0; k < gif.frames.size(); ++k) {
    EXPECT_EQ(gif.frames[k].delay, layout.delay) << "frame " << k;
    EXPECT_EQ(gif.frames[k].localPalette, !layout.globalPalette) << "frame " << k;
  }
}

}  // namespace lancer::test
