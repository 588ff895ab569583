#include "lancer/image/frame_sequence.hpp"

#include <fmt/format.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "lancer/util/input_error.hpp"

namespace lancer {

std::string FramePattern::name(int frame) const {
  return fmt::format("{}{:0{}d}{}", prefix, frame, width, suffix);
}

std::optional<FramePattern> parseFramePattern(const std::string& path) {
  const std::size_t percent = path.find('%');
  if (percent == std::string::npos) return std::nullopt;
  FramePattern pattern;
  pattern.prefix = path.substr(0, percent);
  std::size_t i = percent + 1;
  const std::size_t digitsStart = i;
  while (i < path.size() && std::isdigit(static_cast<unsigned char>(path[i]))) ++i;
  if (i >= path.size() || path[i] != 'd' || (i > digitsStart && path[digitsStart] != '0') ||
      i - digitsStart > 2)
    throw InputError(SourceLocation{path},
                     "a frame-sequence name needs one %d or %0Nd (e.g. frame_%04d.png)");
  if (i > digitsStart) pattern.width = std::stoi(path.substr(digitsStart, i - digitsStart));
  pattern.suffix = path.substr(i + 1);
  if (pattern.suffix.find('%') != std::string::npos)
    throw InputError(SourceLocation{path}, "a frame-sequence name may hold only one %d");
  return pattern;
}

bool completeFrameExists(const std::string& path, int width, int height) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) return false;
  const std::uint64_t size = std::filesystem::file_size(path, error);
  if (error) return false;
  const auto pixels = static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height);
  switch (imageFormatFromPath(path)) {
    case ImageFormat::Png:
      try {
        const Image image = readPng(path);
        return image.width() == width && image.height() == height;
      } catch (const InputError&) {
        return false;  // not a readable PNG: render it again
      }
    case ImageFormat::Ppm:
      return size == fmt::format("P6\n{} {}\n255\n", width, height).size() + 3 * pixels;
    case ImageFormat::Bmp:
      return size ==
             54 + ((3 * static_cast<std::uint64_t>(width) + 3) / 4 * 4) * static_cast<std::uint64_t>(height);
    default:
      return false;  // no cheap check of completeness: render it again
  }
}

namespace {

// Removes `.lancer-PID-*` files of `folder` whose PID names no running process: frames staged by a
// run that was killed (SIGKILL leaves no chance to remove them). A PID now reused by another
// process keeps its files, which is safe; a file that cannot be removed is left.
void removeStaleStagedFrames(const std::filesystem::path& folder) {
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(folder.empty() ? "." : folder, error)) {
    const std::string name = entry.path().filename().string();
    constexpr std::string_view kPrefix = ".lancer-";
    if (!name.starts_with(kPrefix)) continue;
    const std::size_t dash = name.find('-', kPrefix.size());
    if (dash == std::string::npos || dash == kPrefix.size()) continue;
    long pid = 0;
    const std::string digits = name.substr(kPrefix.size(), dash - kPrefix.size());
    if (digits.find_first_not_of("0123456789") != std::string::npos || digits.size() > 9) continue;
    pid = std::stol(digits);
    if (pid <= 0 || pid == ::getpid()) continue;
    if (::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH) continue;  // alive, or not ours to tell
    std::filesystem::remove(entry.path(), error);
  }
}

}  // namespace

StagedFrames::~StagedFrames() {
  for (const auto& [hidden, target] : staged_) std::remove(hidden.c_str());
}

void StagedFrames::write(const std::string& target, const Image& image, const ImageWriteOptions& options) {
  const std::filesystem::path path(target);
  const std::string folder = path.parent_path().string();
  if (std::find(cleanedFolders_.begin(), cleanedFolders_.end(), folder) == cleanedFolders_.end()) {
    removeStaleStagedFrames(path.parent_path());
    cleanedFolders_.push_back(folder);
  }
  // The hidden name keeps the extension, which selects the format.
  const std::string hidden =
      (path.parent_path() / fmt::format(".lancer-{}-{}", ::getpid(), path.filename().string())).string();
  try {
    writeImage(hidden, image, options);
  } catch (const InputError& e) {
    // The user named the target: the hidden name would only puzzle them (nothing of it is left).
    if (e.location().file != hidden) throw;
    throw InputError(SourceLocation{target}, e.message());
  }
  staged_.emplace_back(hidden, target);
}

void StagedFrames::publish() {
  for (auto it = staged_.begin(); it != staged_.end(); it = staged_.erase(it)) {
    if (std::rename(it->first.c_str(), it->second.c_str()) != 0)
      throw InputError(
          SourceLocation{it->second},
          fmt::format("cannot rename {} into place: {}; it and the files staged after it were not written",
                      it->first, std::strerror(errno)));
  }
}

}  // namespace lancer
