#include "lancer/util/thread_count.hpp"

#include <thread>

namespace lancer {

int resolveThreadCount(int requested) {
  if (requested > 0) return requested;
  const unsigned hardware = std::thread::hardware_concurrency();
  return hardware > 0 ? static_cast<int>(hardware) : 1;
}

}  // namespace lancer
