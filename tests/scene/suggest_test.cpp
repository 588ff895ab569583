// Edit distance and the "did you mean" suggestions of scene-file messages.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include <array>
#include <string_view>

#include "lancer/scene/suggest.hpp"

namespace lancer {
namespace {

constexpr std::array<std::string_view, 4> kKeys = {"ka", "kd", "shininess", "look_at"};

TEST(Suggest, EditDistance) {
  EXPECT_EQ(editDistance("", ""), 0u);
  EXPECT_EQ(editDistance("abc", ""), 3u);
  EXPECT_EQ(editDistance("kitten", "sitting"), 3u);
  EXPECT_EQ(editDistance("widht", "width"), 1u);  // one transposition
  EXPECT_EQ(editDistance("Width", "width"), 0u);  // case is ignored
  EXPECT_EQ(editDistance("shinyness", "shininess"), 1u);
}

TEST(Suggest, OffersOnlyCloseNames) {
  EXPECT_EQ(didYouMean("shinyness", kKeys), " (did you mean 'shininess'?)");
  EXPECT_EQ(didYouMean("lookat", kKeys), " (did you mean 'look_at'?)");
  EXPECT_EQ(didYouMean("LookAt", kKeys), " (did you mean 'look_at'?)");
  EXPECT_EQ(didYouMean("kb", kKeys), " (did you mean 'ka'?)");  // ties go to the first
  EXPECT_EQ(didYouMean("colour", kKeys), "");
  EXPECT_EQ(didYouMean("x", std::array<std::string_view, 1>{"y"}), "");
  EXPECT_FALSE(closestName("transparency", kKeys));
}

TEST(Suggest, OptionsAreFoundWithTheirDashesAndWithoutTheirValue) {
  const std::vector<std::string> options = {"--width", "--height", "-o", "--output", "--view", "--samples"};
  EXPECT_EQ(closestOption("--widht", options), "--width");
  EXPECT_EQ(closestOption("--widht=80", options), "--width");
  EXPECT_EQ(closestOption("-width", options), "--width");
  EXPECT_EQ(closestOption("--sample", options), "--samples");
  EXPECT_EQ(closestOption("--veiw", options), "--view");
  EXPECT_FALSE(closestOption("--frobnicate", options));
  EXPECT_FALSE(closestOption("--", options));
  EXPECT_FALSE(closestOption("-=3", options));
}

}  // namespace
}  // namespace lancer
