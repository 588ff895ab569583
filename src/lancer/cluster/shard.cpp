#include "lancer/cluster/shard.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cstdlib>

#include "lancer/util/input_error.hpp"

namespace lancer {
namespace {

// A whole non-negative decimal number and nothing else.
std::optional<long long> parseCount(const std::string& text) {
  long long value = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, error] = std::from_chars(text.data(), end, value);
  if (error != std::errc() || ptr != end || value < 0 || value > 1'000'000'000) return std::nullopt;
  return value;
}

long long requiredNumber(const EnvironmentLookup& environment, const std::string& name, long long fallback,
                         bool required) {
  const std::optional<std::string> text = environment(name);
  if (!text) {
    if (required)
      throw InputError(SourceLocation{name}, fmt::format("{} is not set, but the other SLURM_ARRAY_TASK_* "
                                                         "variables are; is this a SLURM job array?",
                                                         name));
    return fallback;
  }
  const std::optional<long long> value = parseCount(*text);
  if (!value)
    throw InputError(SourceLocation{name},
                     fmt::format("'{}' is not a task number (a whole number from 0)", *text));
  return *value;
}

std::optional<ScheduledShard> slurmArrayShard(const EnvironmentLookup& environment) {
  if (!environment("SLURM_ARRAY_TASK_ID")) return std::nullopt;
  const long long id = requiredNumber(environment, "SLURM_ARRAY_TASK_ID", 0, true);
  const long long min = requiredNumber(environment, "SLURM_ARRAY_TASK_MIN", 0, false);
  const long long step = requiredNumber(environment, "SLURM_ARRAY_TASK_STEP", 1, false);
  long long count = 0;
  if (environment("SLURM_ARRAY_TASK_COUNT")) {
    count = requiredNumber(environment, "SLURM_ARRAY_TASK_COUNT", 0, true);
  } else {
    const long long max = requiredNumber(environment, "SLURM_ARRAY_TASK_MAX", 0, true);
    count = step > 0 && max >= min ? (max - min) / step + 1 : 0;
  }
  // An array such as --array=1-16 or --array=0-30:2 numbers its tasks min, min + step, ...
  if (step <= 0 || id < min || (id - min) % step != 0 || (id - min) / step >= count)
    throw InputError(SourceLocation{"SLURM_ARRAY_TASK_ID"},
                     fmt::format("task {} is not one of the {} tasks from {} in steps of {}; --shard auto "
                                 "needs an evenly stepped array such as --array=0-15 or --array=1-31:2",
                                 id, count, min, step));
  ScheduledShard result;
  result.shard = Shard{static_cast<int>((id - min) / step), static_cast<int>(count)};
  result.source = fmt::format("SLURM_ARRAY_TASK_ID={} (of SLURM_ARRAY_TASK_COUNT={}, min {}, step {})", id,
                              count, min, step);
  return result;
}

std::optional<ScheduledShard> rankShard(const EnvironmentLookup& environment, const std::string& rankName,
                                        const std::string& sizeName) {
  const std::optional<std::string> rankText = environment(rankName);
  const std::optional<std::string> sizeText = environment(sizeName);
  if (!rankText || !sizeText) return std::nullopt;
  const std::optional<long long> rank = parseCount(*rankText);
  const std::optional<long long> size = parseCount(*sizeText);
  if (!rank || !size || *size < 1 || *rank >= *size)
    throw InputError(SourceLocation{rankName}, fmt::format("{}={} with {}={} is not a task of a set",
                                                           rankName, *rankText, sizeName, *sizeText));
  return ScheduledShard{Shard{static_cast<int>(*rank), static_cast<int>(*size)},
                        fmt::format("{}={} (of {}={})", rankName, *rank, sizeName, *size)};
}

}  // namespace

EnvironmentLookup processEnvironment() {
  return [](const std::string& name) -> std::optional<std::string> {
    const char* value = std::getenv(name.c_str());
    if (value == nullptr) return std::nullopt;
    return std::string(value);
  };
}

std::optional<ScheduledShard> scheduledShard(const EnvironmentLookup& environment) {
  if (auto array = slurmArrayShard(environment)) return array;
  if (auto step = rankShard(environment, "SLURM_PROCID", "SLURM_NTASKS")) return step;
  return rankShard(environment, "OMPI_COMM_WORLD_RANK", "OMPI_COMM_WORLD_SIZE");
}

ScheduledShard resolveShard(const std::string& spec, const EnvironmentLookup& environment) {
  const std::optional<ScheduledShard> scheduled = scheduledShard(environment);
  if (spec == "auto") {
    if (!scheduled)
      throw InputError(SourceLocation{"--shard"},
                       "--shard auto found no task number: none of SLURM_ARRAY_TASK_ID, SLURM_PROCID or "
                       "OMPI_COMM_WORLD_RANK is set; give --shard I/N");
    return *scheduled;
  }
  const std::size_t slash = spec.find('/');
  const std::optional<long long> index =
      slash == std::string::npos ? std::nullopt : parseCount(spec.substr(0, slash));
  const std::optional<long long> count =
      slash == std::string::npos ? std::nullopt : parseCount(spec.substr(slash + 1));
  if (!index || !count || *count < 1 || *index >= *count || *count > 1'000'000)
    throw InputError(SourceLocation{"--shard"},
                     fmt::format("'{}' is not a shard: use I/N with 0 <= I < N (e.g. 3/16), or auto", spec));
  const Shard shard{static_cast<int>(*index), static_cast<int>(*count)};
  if (scheduled && scheduled->shard.count > 1 && scheduled->shard != shard)
    throw InputError(SourceLocation{"--shard"},
                     fmt::format("--shard {} disagrees with the scheduler, which started this process as "
                                 "task {} of {} ({}); use --shard auto or the scheduler's numbers",
                                 spec, scheduled->shard.index, scheduled->shard.count, scheduled->source));
  return ScheduledShard{shard, fmt::format("--shard {}", spec)};
}

FrameRange parseFrameRange(const std::string& text, int frameCount) {
  const std::size_t dash = text.find('-');
  const std::optional<long long> first = parseCount(text.substr(0, dash));
  const std::optional<long long> last = dash == std::string::npos ? first : parseCount(text.substr(dash + 1));
  if (!first || !last || *first > *last)
    throw InputError(
        SourceLocation{"--frame-range"},
        fmt::format("'{}' is not a frame range: use A-B with A <= B (e.g. 0-89), or one frame A", text));
  if (*last >= frameCount)
    throw InputError(SourceLocation{"--frame-range"},
                     fmt::format("frame {} is past the end: the animation has {} frames, 0 to {}", *last,
                                 frameCount, frameCount - 1));
  return FrameRange{static_cast<int>(*first), static_cast<int>(*last)};
}

std::vector<int> shardFrames(int frameCount, const std::optional<FrameRange>& range, const Shard& shard) {
  const int first = range ? range->first : 0;
  const int last = range ? range->last : frameCount - 1;
  std::vector<int> frames;
  for (int k = first; k <= last; ++k)
    if (k % shard.count == shard.index) frames.push_back(k);
  return frames;
}

std::string describeFrames(const std::vector<int>& frames) {
  if (frames.empty()) return "no frames";
  std::string text;
  const std::size_t shown = std::min<std::size_t>(frames.size(), 4);
  for (std::size_t i = 0; i < shown; ++i) text += fmt::format("{}{}", i ? ", " : "", frames[i]);
  if (frames.size() > shown) text += fmt::format(" ... {}", frames.back());
  return text + fmt::format(" ({} frame{})", frames.size(), frames.size() == 1 ? "" : "s");
}

}  // namespace lancer
