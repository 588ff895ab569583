// Numbered frames are staged as hidden files (.lancer-PID-NAME) and published together; a run killed
// by SIGKILL leaves its hidden frames, and the next run writing frames into that folder removes
// those whose PID no running process has.
#include <gtest/gtest.h>
#include <unistd.h>

#include <string>

#include "lancer/image/frame_sequence.hpp"
#include "support/files.hpp"

namespace lancer {
namespace {

TEST(StagedFrames, TheNextRunRemovesTheHiddenFramesOfAKilledOne) {
  const test::ScratchFolder folder;
  const std::string dead = ".lancer-999999999-frame_0003.png";  // above any pid_max: no such process
  const std::string alive = ".lancer-" + std::to_string(::getppid()) + "-frame_0003.png";
  folder.write(dead, "stale");
  folder.write(alive, "another run's");
  folder.write(".lancer-notapid-frame.png", "not ours");
  folder.write("frame_0003.png", "kept until published");
  Image image(2, 2);
  {
    StagedFrames frames;
    frames.write(folder.file("frame_0000.png"), image, ImageWriteOptions{});
    frames.publish();
  }
  EXPECT_EQ(folder.entries(), (std::vector<std::string>{alive, ".lancer-notapid-frame.png", "frame_0000.png",
                                                        "frame_0003.png"}));
}

}  // namespace
}  // namespace lancer
