// Seconds since a start, on the steady clock: what every "load ... s, build ... s" figure and
// progress line measures.
#pragma once

#include <chrono>

namespace lancer {

class Stopwatch {
 public:
  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace lancer
