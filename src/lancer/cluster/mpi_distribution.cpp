#include "lancer/cluster/mpi_distribution.hpp"

#include <fmt/format.h>

#include <charconv>
#include <stdexcept>

#if LANCER_HAVE_MPI
#include <mpi.h>
#include <sched.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstring>
#include <deque>
#include <exception>
#include <limits>
#include <map>
#include <mutex>
#include <thread>
#include <vector>

#include "lancer/util/thread_count.hpp"
#endif

namespace lancer {

std::optional<int> mpiLaunchSize(const EnvironmentLookup& environment) {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"}) {
    if (const std::optional<std::string> text = environment(name)) {
      int size = 0;
      const auto [end, error] = std::from_chars(text->data(), text->data() + text->size(), size);
      if (error == std::errc() && end == text->data() + text->size() && size > 0) return size;
    }
  }
  return std::nullopt;
}

#if !LANCER_HAVE_MPI

bool mpiBuilt() { return false; }
std::unique_ptr<WorkDistribution> makeMpiDistribution() {
  throw std::logic_error("makeMpiDistribution: this lancer was built without MPI");
}
std::string mpiRankLabel() { return {}; }
void endMpi(int) {}

#else

namespace {

constexpr int kTagRequest = 1;       // worker -> 0: ready for its first item
constexpr int kTagResultHeader = 2;  // worker -> 0: {item, width, height} of the result that follows
constexpr int kTagResultPixels = 3;  // worker -> 0: the pixels, linear float RGBA
constexpr int kTagAssign = 4;        // 0 -> worker: the item to render next, or kNoMoreItems
constexpr int kNoMoreItems = -1;
// How long a waiting rank sleeps between polls: short against any item's render time, long enough
// that a waiting rank's core does no measurable work.
constexpr auto kPollPause = std::chrono::microseconds(500);

struct MpiState {
  bool initialised = false;
  int rank = 0, size = 1;
  int ranksSharingCpus = 1;  // the ranks of this node whose affinity masks meet this one's, this one included
};
MpiState gMpi;

// How many ranks of this node may run on the CPUs this rank may run on: all of them when they are not
// bound (`mpirun --bind-to none`, one SLURM cpuset), none but this one when each is bound to its own
// cores, the ranks of a socket under --bind-to socket. A mask that cannot be read counts as every CPU.
int countRanksSharingCpus(MPI_Comm node, int nodeRanks) {
  cpu_set_t mine;
  CPU_ZERO(&mine);
  if (sched_getaffinity(0, sizeof mine, &mine) != 0) std::memset(&mine, 0xff, sizeof mine);
  std::vector<cpu_set_t> masks(static_cast<std::size_t>(nodeRanks));
  MPI_Allgather(&mine, sizeof mine, MPI_BYTE, masks.data(), sizeof mine, MPI_BYTE, node);
  int sharing = 0;
  for (cpu_set_t& other : masks) {
    CPU_AND(&other, &other, &mine);
    if (CPU_COUNT(&other) > 0) ++sharing;
  }
  return std::max(1, sharing);
}

void initialiseMpi() {
  if (gMpi.initialised) return;
  int provided = 0;
  // Only the calling (main) thread makes MPI calls; rank 0's render thread never does.
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  MPI_Comm_rank(MPI_COMM_WORLD, &gMpi.rank);
  MPI_Comm_size(MPI_COMM_WORLD, &gMpi.size);
  // A lost peer makes a call fail instead of aborting this rank at once: rank 0 then unwinds and
  // removes its temporary files before the job ends.
  MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
  MPI_Comm node = MPI_COMM_NULL;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
  if (node != MPI_COMM_NULL) {
    int nodeRanks = 1;
    MPI_Comm_size(node, &nodeRanks);
    gMpi.ranksSharingCpus = countRanksSharingCpus(node, nodeRanks);
    MPI_Comm_free(&node);
  }
  gMpi.initialised = true;
}

// Throws when an MPI call failed (a rank died): the command fails, its outputs untouched.
void check(int status, const char* what) {
  if (status == MPI_SUCCESS) return;
  char text[MPI_MAX_ERROR_STRING] = {};
  int length = 0;
  MPI_Error_string(status, text, &length);
  throw std::runtime_error(fmt::format("MPI {} failed: {} (did another rank die?)", what, text));
}

// Completes `request` without spinning: MPI_Test, then a short sleep. False when cancelled first.
bool waitQuietly(MPI_Request& request, const std::atomic<bool>* cancel) {
  for (;;) {
    int done = 0;
    check(MPI_Test(&request, &done, MPI_STATUS_IGNORE), "MPI_Test");
    if (done != 0) return true;
    if (cancel != nullptr && cancel->load()) return false;
    std::this_thread::sleep_for(kPollPause);
  }
}

int pixelCount(const Image& image) {
  const std::size_t floats = image.pixels().size() * 4;
  if (floats > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    throw std::runtime_error(fmt::format("a work item of {}x{} pixels is too large for one MPI message",
                                         image.width(), image.height()));
  return static_cast<int>(floats);
}

class MpiDistribution final : public WorkDistribution {
 public:
  int rank() const override { return gMpi.rank; }
  int ranks() const override { return gMpi.size; }
  // OMP_NUM_THREADS and SLURM_CPUS_PER_TASK are per rank already; the CPUs of an affinity mask are
  // shared with the other ranks of the node that may run on them.
  int defaultThreads() const override {
    const DefaultThreadCount threads = defaultThreadCount();
    if (threads.source != ThreadCountSource::kAffinity) return threads.count;
    return std::max(1, threads.count / gMpi.ranksSharingCpus);
  }
  bool run(const DistributedWork& work) override { return gMpi.rank == 0 ? coordinate(work) : follow(work); }

 private:
  // A rank other than 0: ask for an item, render it, send it back (which asks for the next).
  static bool follow(const DistributedWork& work) {
    int none = kNoMoreItems;
    MPI_Request request = MPI_REQUEST_NULL;
    check(MPI_Isend(&none, 1, MPI_INT, 0, kTagRequest, MPI_COMM_WORLD, &request), "MPI_Isend");
    if (!waitQuietly(request, work.cancel)) return false;
    for (;;) {
      int item = kNoMoreItems;
      check(MPI_Irecv(&item, 1, MPI_INT, 0, kTagAssign, MPI_COMM_WORLD, &request), "MPI_Irecv");
      if (!waitQuietly(request, work.cancel)) return false;
      if (item == kNoMoreItems) return true;
      Image pixels = work.render(item);
      if (work.cancel != nullptr && work.cancel->load()) return false;
      int header[3] = {item, pixels.width(), pixels.height()};
      MPI_Request sends[2];
      check(MPI_Isend(header, 3, MPI_INT, 0, kTagResultHeader, MPI_COMM_WORLD, &sends[0]), "MPI_Isend");
      check(MPI_Isend(pixels.pixels().data(), pixelCount(pixels), MPI_FLOAT, 0, kTagResultPixels,
                      MPI_COMM_WORLD, &sends[1]),
            "MPI_Isend");
      if (!waitQuietly(sends[0], work.cancel) || !waitQuietly(sends[1], work.cancel)) return false;
    }
  }

  // Rank 0: this thread talks MPI and delivers in order; a render thread renders items here too.
  static bool coordinate(const DistributedWork& work) {
    const auto cancelled = [&] { return work.cancel != nullptr && work.cancel->load(); };
    std::mutex mutex;
    std::condition_variable changed;  // an item was finished here, or the window moved
    int next = 0, delivered = 0;
    bool stopping = false;
    std::exception_ptr renderError;
    std::map<int, Image> finished;  // rendered (here or elsewhere), not yet delivered
    const auto mayStart = [&] { return next < work.itemCount && next < delivered + work.window; };

    std::jthread renderer([&] {
      for (;;) {
        int item = 0;
        {
          std::unique_lock lock(mutex);
          changed.wait(lock, [&] { return stopping || mayStart() || next >= work.itemCount; });
          if (stopping || next >= work.itemCount) return;
          item = next++;
        }
        try {
          Image pixels = work.render(item);
          std::lock_guard lock(mutex);
          finished.emplace(item, std::move(pixels));
        } catch (...) {
          std::lock_guard lock(mutex);
          renderError = std::current_exception();
          stopping = true;
        }
        changed.notify_all();
      }
    });
    struct StopRenderer {
      std::mutex& mutex;
      std::condition_variable& changed;
      bool& stopping;
      ~StopRenderer() {
        {
          std::lock_guard lock(mutex);
          stopping = true;
        }
        changed.notify_all();
      }
    } stopRenderer{mutex, changed, stopping};

    std::deque<int> waiting;  // ranks that asked for an item the window has no room for yet
    int released = 0;         // ranks told there is nothing more
    const int followers = gMpi.size - 1;
    while (delivered < work.itemCount || released < followers) {
      if (cancelled()) return false;
      bool busy = false;
      int flag = 0;
      MPI_Status status;
      check(MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &status), "MPI_Iprobe");
      if (flag != 0) {
        busy = true;
        const int source = status.MPI_SOURCE;
        if (status.MPI_TAG == kTagRequest) {
          int ignored = 0;
          check(MPI_Recv(&ignored, 1, MPI_INT, source, kTagRequest, MPI_COMM_WORLD, MPI_STATUS_IGNORE),
                "MPI_Recv");
        } else {
          int header[3] = {};
          check(MPI_Recv(header, 3, MPI_INT, source, kTagResultHeader, MPI_COMM_WORLD, MPI_STATUS_IGNORE),
                "MPI_Recv");
          Image pixels(header[1], header[2]);
          // Not a blocking receive: a rank stopped by Ctrl-C after its header never sends the pixels,
          // and rank 0 must still notice the cancel and remove its temporary file.
          MPI_Request request = MPI_REQUEST_NULL;
          check(MPI_Irecv(pixels.pixels().data(), pixelCount(pixels), MPI_FLOAT, source, kTagResultPixels,
                          MPI_COMM_WORLD, &request),
                "MPI_Irecv");
          if (!waitQuietly(request, work.cancel)) return false;
          std::lock_guard lock(mutex);
          finished.emplace(header[0], std::move(pixels));
        }
        waiting.push_back(source);
      }
      while (!waiting.empty()) {
        int item = kNoMoreItems;
        {
          std::lock_guard lock(mutex);
          if (mayStart()) {
            item = next++;
          } else if (next < work.itemCount) {
            break;  // the window is full: this rank waits for a delivery
          }
        }
        check(MPI_Send(&item, 1, MPI_INT, waiting.front(), kTagAssign, MPI_COMM_WORLD), "MPI_Send");
        if (item == kNoMoreItems) ++released;
        waiting.pop_front();
        busy = true;
      }
      for (;;) {
        Image pixels;
        {
          std::lock_guard lock(mutex);
          if (renderError) std::rethrow_exception(renderError);
          const auto it = finished.find(delivered);
          if (it == finished.end()) break;
          pixels = std::move(it->second);
          finished.erase(it);
        }
        if (cancelled()) return false;
        work.deliver(delivered, pixels);
        {
          std::lock_guard lock(mutex);
          ++delivered;
        }
        changed.notify_all();
        if (work.onDelivered) work.onDelivered(delivered, work.itemCount);
        busy = true;
      }
      if (!busy) {
        std::unique_lock lock(mutex);
        changed.wait_for(lock, kPollPause);
      }
    }
    return true;
  }
};

}  // namespace

bool mpiBuilt() { return true; }

std::unique_ptr<WorkDistribution> makeMpiDistribution() {
  initialiseMpi();
  return std::make_unique<MpiDistribution>();
}

std::string mpiRankLabel() {
  return gMpi.initialised ? fmt::format("rank {} of {}", gMpi.rank, gMpi.size) : std::string();
}

void endMpi(int exitCode) {
  if (!gMpi.initialised) return;
  // Rank 0 has removed its temporary files by now and may end the others at once. Any other rank
  // leaves without MPI_Finalize: the launcher then ends the job with SIGTERM, which rank 0 handles
  // like Ctrl-C (an MPI_Abort here would SIGKILL rank 0 mid-write and leave its temporary file).
  if (exitCode != 0) {
    if (gMpi.rank == 0) MPI_Abort(MPI_COMM_WORLD, exitCode);
    return;
  }
  // Ranks that finish early wait here for rank 0's writing; MPI_Finalize alone would spin.
  MPI_Request barrier = MPI_REQUEST_NULL;
  try {
    check(MPI_Ibarrier(MPI_COMM_WORLD, &barrier), "MPI_Ibarrier");
    waitQuietly(barrier, nullptr);
  } catch (const std::runtime_error&) {
    return;  // a rank died after this one's work was done: nothing left to finalise with
  }
  MPI_Finalize();
}

#endif

}  // namespace lancer
