// Output safety: a failed or abandoned write never damages an existing file and leaves no
// temporary file behind; failures are one-line InputErrors naming the file.
#include "lancer/image/atomic_file.hpp"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <string>
#include <vector>

#include "lancer/image/gif_writer.hpp"
#include "lancer/image/image_io.hpp"
#include "support/file_size_limit.hpp"
#include "support/files.hpp"
#include "support/input_errors.hpp"
#include "support/test_images.hpp"

namespace lancer {
namespace {

using test::messageOf;
using test::noise;
using test::readBytes;
using test::ScratchFolder;

const std::vector<std::uint8_t> kOldContent = {'o', 'l', 'd', '\n'};

TEST(AtomicFile, CommitPublishesTheFileAndLeavesNoTemporary) {
  ScratchFolder folder;
  AtomicFileWriter file(folder.file("a.bin"));
  EXPECT_EQ(file.tempPath().rfind(folder.file(".a.bin.tmp-"), 0), 0u) << file.tempPath();
  EXPECT_TRUE(file.write(kOldContent));
  EXPECT_EQ(folder.entries().size(), 1u);  // only the temporary file so far
  file.commit();
  test::expectOnlyFile(folder, "a.bin", kOldContent);
}

TEST(AtomicFile, ReplacesAnExistingFileWhole) {
  ScratchFolder folder;
  test::writeBytes(folder.file("a.bin"), std::vector<std::uint8_t>(10000, 'x'));
  writeFileAtomically(folder.file("a.bin"), kOldContent);
  test::expectOnlyFile(folder, "a.bin", kOldContent);
}

TEST(AtomicFile, AbandonedWriteLeavesTheOldFileAndNoTemporary) {
  ScratchFolder folder;
  test::writeBytes(folder.file("a.png"), kOldContent);
  {
    AtomicFileWriter file(folder.file("a.png"));
    file.write(std::vector<std::uint8_t>(5000, 'n'));
  }  // e.g. an exception while rendering unwinds past the writer
  test::expectOnlyFile(folder, "a.png", kOldContent);
  {
    GifWriter gif(folder.file("b.gif"), 8, 8);
    gif.addFrame(Image(8, 8));
  }  // never finished
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"a.png"});
}

TEST(AtomicFile, MissingFolderIsAClearError) {
  ScratchFolder folder;
  const std::string path = folder.file("missing/out.png");
  EXPECT_EQ(messageOf([&] { writeImage(path, Image(4, 4)); }),
            path + ": error: cannot write here: the folder '" + folder.file("missing") + "' does not exist");
  EXPECT_EQ(messageOf([&] { GifWriter(path, 4, 4); }),
            path + ": error: cannot write here: the folder '" + folder.file("missing") + "' does not exist");
  EXPECT_TRUE(folder.entries().empty());
}

TEST(AtomicFile, FolderThatIsAFileIsAClearError) {
  ScratchFolder folder;
  test::writeBytes(folder.file("plain"), kOldContent);
  const std::string path = folder.file("plain/out.bmp");
  EXPECT_EQ(messageOf([&] { writeImage(path, Image(4, 4)); }),
            path + ": error: cannot write here: '" + folder.file("plain") + "' is not a folder");
  EXPECT_EQ(readBytes(folder.file("plain")), kOldContent);
}

TEST(AtomicFile, TargetThatIsAFolderIsAClearError) {
  ScratchFolder folder;
  std::filesystem::create_directory(folder.file("out.png"));
  EXPECT_EQ(messageOf([&] { writeImage(folder.file("out.png"), Image(4, 4)); }),
            folder.file("out.png") + ": error: cannot write here: this is a folder, not a file");
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"out.png"});
}

TEST(AtomicFile, ReadOnlyFolderIsAClearErrorAndKeepsTheOldFile) {
  if (::geteuid() == 0)
    GTEST_SKIP() << "root ignores folder permissions; see the missing-folder and size-limit tests";
  ScratchFolder folder;
  test::writeBytes(folder.file("a.png"), kOldContent);
  ::chmod(folder.path().c_str(), 0555);
  const std::string message = messageOf([&] { writeImage(folder.file("a.png"), Image(4, 4)); });
  ::chmod(folder.path().c_str(), 0755);
  EXPECT_EQ(message, folder.file("a.png") +
                         ": error: cannot write here: no permission to create files in the folder '" +
                         folder.path().string() + "'");
  test::expectOnlyFile(folder, "a.png", kOldContent);
}

TEST(AtomicFile, NewFileGetsUmaskPermissionsAndAReplacedOneKeepsItsOwn) {
  ScratchFolder folder;
  const mode_t previousUmask = ::umask(027);
  writeFileAtomically(folder.file("new.bin"), kOldContent);
  ::umask(previousUmask);
  struct stat info {};
  ASSERT_EQ(::stat(folder.file("new.bin").c_str(), &info), 0);
  EXPECT_EQ(info.st_mode & 0777, 0640u);
  ::chmod(folder.file("new.bin").c_str(), 0604);
  writeFileAtomically(folder.file("new.bin"), kOldContent);
  ASSERT_EQ(::stat(folder.file("new.bin").c_str(), &info), 0);
  EXPECT_EQ(info.st_mode & 0777, 0604u);
}

TEST(AtomicFile, RelativePathWritesIntoTheCurrentFolder) {
  ScratchFolder folder;
  const std::filesystem::path previous = std::filesystem::current_path();
  std::filesystem::current_path(folder.path());
  writeFileAtomically("plain.bin", kOldContent);
  std::filesystem::current_path(previous);
  test::expectOnlyFile(folder, "plain.bin", kOldContent);
}

TEST(AtomicFile, InterruptHandlerRemovesTheTemporaryFile) {
  ScratchFolder folder;
  test::writeBytes(folder.file("a.png"), kOldContent);
  const pid_t child = ::fork();
  if (child == 0) {
    ::signal(SIGINT, [](int signalNumber) {
      removePendingTemporaryFiles();
      ::signal(signalNumber, SIG_DFL);
      ::raise(signalNumber);
    });
    AtomicFileWriter first(folder.file("a.png"));
    AtomicFileWriter second(folder.file("b.png"));
    first.write(std::vector<std::uint8_t>(100000, 'n'));
    ::raise(SIGINT);  // as Ctrl-C in the middle of writing
    ::_exit(3);
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGINT) << status;
  test::expectOnlyFile(folder, "a.png", kOldContent);
}

TEST(AtomicFile, CommittedOrDiscardedFilesAreNoLongerTracked) {
  ScratchFolder folder;
  { AtomicFileWriter abandoned(folder.file("x.bin")); }
  writeFileAtomically(folder.file("a.bin"), kOldContent);
  const std::string reused = folder.file(".a.bin.tmp-reused");
  test::writeBytes(reused, kOldContent);  // a file the handler must not touch
  removePendingTemporaryFiles();
  EXPECT_EQ(folder.entries(), (std::vector<std::string>{".a.bin.tmp-reused", "a.bin"}));
}

// Writes `path` under a 4 KiB file size limit; returns the InputError's message.
std::string writeUnderFileSizeLimit(const std::string& path) {
  return test::underFileSizeLimit(4096, [&] {
    return messageOf([&] {
      if (path.ends_with(".gif")) {
        GifOptions options;
        options.palette = GifPalette::PerFrame;  // streams frames: fails part-way through the file
        GifWriter gif(path, 64, 64, options);
        for (int k = 0; k < 4; ++k) gif.addFrame(noise(64, 64));
        gif.finish();
      } else {
        writeImage(path, noise(64, 64));
      }
    });
  });
}

class FileSizeLimit : public testing::TestWithParam<std::string> {};

TEST_P(FileSizeLimit, FailedWriteKeepsTheOldFileAndLeavesNoTemporary) {
  ScratchFolder folder;
  const std::string path = folder.file("out" + GetParam());
  test::writeBytes(path, kOldContent);
  EXPECT_EQ(writeUnderFileSizeLimit(path),
            path +
                ": error: writing failed: the file would exceed the file size limit (see 'ulimit -f'); "
                "the existing file was left unchanged");
  test::expectOnlyFile(folder, "out" + GetParam(), kOldContent);
}

TEST(AtomicFile, RequireWritableSaysWhatTheWriterWouldAndLeavesNothing) {
  ScratchFolder folder;
  EXPECT_EQ(test::messageOf([&] { requireWritable(folder.file("missing/out.png")); }),
            folder.file("missing/out.png") + ": error: cannot write here: the folder '" +
                folder.file("missing") + "' does not exist");
  requireWritable(folder.file("out.png"));
  EXPECT_TRUE(folder.entries().empty());
}

TEST(AtomicFile, SameOutputPathSeesThroughDotsAndLinks) {
  ScratchFolder folder;
  folder.write("sub/a.png", "a");
  ASSERT_EQ(::symlink(folder.file("sub").c_str(), folder.file("link").c_str()), 0);
  EXPECT_TRUE(sameOutputPath(folder.file("sub/a.png"), folder.file("link/../sub/./a.png")));
  EXPECT_TRUE(sameOutputPath(folder.file("sub/a.png"), folder.file("link/a.png")));
  EXPECT_TRUE(sameOutputPath(folder.file("sub/new.png"), folder.file("link/new.png")));  // not written yet
  EXPECT_FALSE(sameOutputPath(folder.file("sub/a.png"), folder.file("sub/b.png")));
}

TEST_P(FileSizeLimit, FailedFirstWriteLeavesNothing) {
  ScratchFolder folder;
  const std::string path = folder.file("out" + GetParam());
  EXPECT_EQ(writeUnderFileSizeLimit(path),
            path +
                ": error: writing failed: the file would exceed the file size limit (see 'ulimit -f'); "
                "no file was written");
  EXPECT_TRUE(folder.entries().empty());
}

INSTANTIATE_TEST_SUITE_P(EveryWriter, FileSizeLimit, testing::Values(".png", ".bmp", ".ppm", ".gif"),
                         [](const testing::TestParamInfo<std::string>& param) {
                           return param.param.substr(1);
                         });

}  // namespace
}  // namespace lancer
