// The exact sweep of the bounds in a binned split's window, shared by both SAH builders: the planes
// the event sweep of Wald & Havran 2006 would try there, each priced with planar triangles on
// either side.
#pragma once

#include <algorithm>
#include <cstdint>
#include <span>

namespace lancer {

// `events`: sorted by position, then type (0 end, 1 planar, 2 start); nl and nr are the counts
// left and right of the window's first plane. For each plane strictly inside (planeCost.lo,
// planeCost.hi), calls candidate(pos, planarsLeft, cost) with the planars on the left, then on
// the right.
template <typename Event, typename PlaneCost, typename Candidate>
void sweepWindowEvents(std::span<const Event> events, const PlaneCost& planeCost, std::uint32_t nl,
                       std::uint32_t nr, Candidate&& candidate) {
  for (std::size_t i = 0; i < events.size();) {
    const float p = events[i].pos;
    std::uint32_t ends = 0, planars = 0, starts = 0;
    for (; i < events.size() && events[i].pos == p; ++i) {
      ends += events[i].type == 0;
      planars += events[i].type == 1;
      starts += events[i].type == 2;
    }
    nr -= std::min(nr, planars + ends);
    if (p > planeCost.lo && p < planeCost.hi) {
      candidate(p, true, planeCost(p, nl + planars, nr));
      candidate(p, false, planeCost(p, nl, nr + planars));
    }
    nl += starts + planars;
  }
}

}  // namespace lancer
