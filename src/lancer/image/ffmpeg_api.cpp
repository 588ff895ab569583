#include "lancer/image/ffmpeg_api.hpp"

#if LANCER_HAVE_FFMPEG
#include <dlfcn.h>

#include <mutex>
#include <optional>

#include <fmt/format.h>

#include "lancer/util/input_error.hpp"

namespace lancer {

namespace {

#define LANCER_STRINGIFY_(x) #x
#define LANCER_STRINGIFY(x) LANCER_STRINGIFY_(x)

// The sonames the headers were written for: another major version has another ABI.
constexpr const char* kAvutil = "libavutil.so." LANCER_STRINGIFY(LIBAVUTIL_VERSION_MAJOR);
constexpr const char* kSwscale = "libswscale.so." LANCER_STRINGIFY(LIBSWSCALE_VERSION_MAJOR);
constexpr const char* kAvcodec = "libavcodec.so." LANCER_STRINGIFY(LIBAVCODEC_VERSION_MAJOR);
constexpr const char* kAvformat = "libavformat.so." LANCER_STRINGIFY(LIBAVFORMAT_VERSION_MAJOR);

struct Loaded {
  FfmpegApi api;
  std::string error;  // why loading failed; empty when it did not
};

std::string dlWhy() {
  const char* why = dlerror();
  return why != nullptr ? why : "unknown error";
}

Loaded load() {
  Loaded loaded;
  // Never closed: the writer's objects and FFmpeg's own threads may outlive any one video.
  void* avutil = dlopen(kAvutil, RTLD_NOW | RTLD_LOCAL);
  void* swscale = avutil != nullptr ? dlopen(kSwscale, RTLD_NOW | RTLD_LOCAL) : nullptr;
  void* avcodec = swscale != nullptr ? dlopen(kAvcodec, RTLD_NOW | RTLD_LOCAL) : nullptr;
  void* avformat = avcodec != nullptr ? dlopen(kAvformat, RTLD_NOW | RTLD_LOCAL) : nullptr;
  if (avformat == nullptr) {
    loaded.error = fmt::format("cannot load FFmpeg ({})", dlWhy());
    return loaded;
  }
#define LANCER_FFMPEG_LOOKUP(library, function)                                                \
  loaded.api.function = reinterpret_cast<decltype(&::function)>(dlsym(library, #function));    \
  if (loaded.api.function == nullptr) {                                                        \
    loaded.error = fmt::format("FFmpeg's lib" #library " has no " #function " ({})", dlWhy()); \
    return loaded;                                                                             \
  }
  LANCER_FFMPEG_FUNCTIONS(LANCER_FFMPEG_LOOKUP)
#undef LANCER_FFMPEG_LOOKUP
  return loaded;
}

}  // namespace

const FfmpegApi& ffmpegApi(const std::string& path) {
  static std::once_flag once;
  static std::optional<Loaded> loaded;
  std::call_once(once, [] { loaded = load(); });
  if (!loaded->error.empty())
    throw InputError(SourceLocation{path},
                     fmt::format("{}: install FFmpeg's libraries (Debian: libavcodec{} libavformat{} "
                                 "libswscale{}, which scripts/setup.sh installs), or write .gif, an "
                                 "animated .png or numbered frames",
                                 loaded->error, LIBAVCODEC_VERSION_MAJOR, LIBAVFORMAT_VERSION_MAJOR,
                                 LIBSWSCALE_VERSION_MAJOR));
  return loaded->api;
}

}  // namespace lancer
#endif
