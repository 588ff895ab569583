// How the kd-tree builds fork subtrees (kd/binned_build.cpp, kd/sah_build.cpp, kd/median_build.cpp):
// at most `threads` build at once, a subtree goes to a thread of its own only when one is free, and a
// thread that waits for the subtree it forked lends its place meanwhile. The trees never depend on
// it: only who builds which subtree does.
#pragma once

#include <atomic>
#include <chrono>
#include <cstddef>
#include <future>
#include <span>
#include <thread>
#include <utility>
#include <vector>

namespace lancer {

class BuildThreads {
 public:
  // `threads` >= 1 (resolved); the calling thread is one of them.
  explicit BuildThreads(int threads) : threads_(threads), spare_(threads - 1) {}

  int count() const { return threads_; }
  // Whether a thread is free now (a hint: fork() may still find none).
  bool spare() const { return spare_.load() > 0; }

  // Starts task() on a thread of its own when one is free; an invalid future (the caller runs the
  // subtree itself) when none is. The thread is handed back when the task ends.
  template <typename Task>
  std::future<void> fork(Task&& task) {
    if (!takeSpare()) return {};
    return std::async(std::launch::async, [this, task = std::forward<Task>(task)]() mutable {
      Release release{spare_};
      task();
    });
  }

  // Waits for a task fork() started (an invalid future: nothing to wait for). Waiting, this thread
  // runs nothing, so it lends its place to the others (the forked subtree may have far more left
  // to do than this thread had), and takes a place again before going on.
  void join(std::future<void>& task) {
    if (!task.valid()) return;
    if (task.wait_for(std::chrono::seconds(0)) != std::future_status::ready) {
      ++spare_;
      task.wait();
      while (!takeSpare()) std::this_thread::yield();
    }
    task.get();
  }

  // run(item) for every item, taken in order (callers put the biggest subtrees first) by the
  // calling thread and every thread free, each item by whichever thread falls free first.
  template <typename Item, typename Run>
  void runEach(std::span<Item> items, Run&& run) {
    std::atomic<std::size_t> next{0};
    auto work = [&] {
      for (std::size_t k; (k = next.fetch_add(1)) < items.size();) run(items[k]);
    };
    std::vector<std::future<void>> helpers;
    while (helpers.size() + 1 < items.size()) {
      std::future<void> helper = fork(work);
      if (!helper.valid()) break;
      helpers.push_back(std::move(helper));
    }
    work();
    for (std::future<void>& helper : helpers) join(helper);
  }

 private:
  struct Release {
    std::atomic<int>& spare;
    ~Release() { ++spare; }
  };

  bool takeSpare() {
    int spare = spare_.load();
    while (spare > 0 && !spare_.compare_exchange_weak(spare, spare - 1)) {
    }
    return spare > 0;
  }

  int threads_;
  std::atomic<int> spare_;
};

}  // namespace lancer
