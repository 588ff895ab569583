#include "lancer/cluster/work_distribution.hpp"

namespace lancer {

bool LocalDistribution::run(const DistributedWork& work) {
  const auto cancelled = [&] { return work.cancel != nullptr && work.cancel->load(); };
  for (int item = 0; item < work.itemCount; ++item) {
    if (cancelled()) return false;
    const Image pixels = work.render(item);
    if (cancelled()) return false;
    work.deliver(item, pixels);
    if (work.onDelivered) work.onDelivered(item + 1, work.itemCount);
  }
  return true;
}

}  // namespace lancer
