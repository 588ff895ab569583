// `--gmsh-view` takes an optional value (the options file; without one, MESH.msh.opt beside the
// mesh), so it may come before the input or after it: `lancer render --gmsh-view part.msh`,
// `lancer render part.msh --gmsh-view` and `--gmsh-view FILE.opt` in either place give one image.
#include <gtest/gtest.h>

#include <string>

#include "support/cli.hpp"
#include "support/files.hpp"

namespace lancer {
namespace {

using test::quoted;

// part.msh with the euler_xyz view beside it as part.msh.opt, and the same view as view.opt.
struct ViewFolder {
  test::ScratchFolder folder;
  ViewFolder() {
    folder.copy(test::dataFile("gmsh_view/part.msh"), "part.msh");
    folder.copy(test::dataFile("gmsh_view/euler_xyz.opt"), "part.msh.opt");
    folder.copy(test::dataFile("gmsh_view/euler_xyz.opt"), "view.opt");
  }
  std::string mesh() const { return quoted(folder.file("part.msh")); }
  std::string view() const { return quoted(folder.file("view.opt")); }
  // Renders `lancer render ARGUMENTS -o NAME` small; returns the output path.
  std::string render(const std::string& arguments, const std::string& name) const {
    const std::string out = folder.file(name);
    const test::CommandResult result =
        test::runCli("render " + arguments + " -q --width 64 --height 48 -o " + quoted(out));
    EXPECT_EQ(result.exitCode, 0) << arguments << "\n" << result.output;
    return out;
  }
};

TEST(GmshViewCli, TheViewBeforeOrAfterTheInputGivesOneImage) {
  const ViewFolder views;
  const std::string after = views.render(views.mesh() + " --gmsh-view", "after.png");
  test::expectSameFile(views.render("--gmsh-view " + views.mesh(), "before.png"), after);
  test::expectSameFile(views.render("--gmsh-view " + views.view() + " " + views.mesh(), "file_before.png"),
                       after);
  test::expectSameFile(views.render(views.mesh() + " --gmsh-view " + views.view(), "file_after.png"), after);
  // The view was used: without it the quick look's own camera draws something else.
  EXPECT_NE(test::readPictureBytes(views.render(views.mesh(), "plain.png")), test::readPictureBytes(after));
}

TEST(GmshViewCli, AnimateTakesTheViewBeforeTheInputToo) {
  const ViewFolder views;
  for (const std::string& order : {"--gmsh-view " + views.mesh(), views.mesh() + " --gmsh-view"}) {
    const test::CommandResult result =
        test::runCli("animate " + order + " -q --frames 2 --width 32 --height 24 -o " +
                     quoted(views.folder.file("turn.gif")));
    EXPECT_EQ(result.exitCode, 0) << order << "\n" << result.output;
  }
}

TEST(GmshViewCli, AnOptionsFileAloneIsNoInput) {
  const ViewFolder views;
  for (const std::string& command :
       {"render --gmsh-view " + views.view(), std::string("render"), "animate --gmsh-view " + views.view()}) {
    const test::CommandResult result = test::runCli(command + " -o " + quoted(views.folder.file("x.png")));
    EXPECT_EQ(result.exitCode, 2) << command << "\n" << result.output;
    EXPECT_TRUE(test::contains(result.output, "input is required")) << command << "\n" << result.output;
  }
}

}  // namespace
}  // namespace lancer
