// Where the time before the first ray goes (`lancer render --timings`): named stages and their wall
// seconds, in the order they first ran; a stage met again (one per mesh of a scene) adds up.
#pragma once

#include <string>
#include <vector>

namespace lancer {

struct StageTimes {
  struct Stage {
    std::string name;
    double seconds = 0;
  };
  std::vector<Stage> stages;

  void add(const std::string& name, double seconds) {
    for (Stage& stage : stages)
      if (stage.name == name) {
        stage.seconds += seconds;
        return;
      }
    stages.push_back({name, seconds});
  }
  double totalSeconds() const {
    double total = 0;
    for (const Stage& stage : stages) total += stage.seconds;
    return total;
  }
};

}  // namespace lancer
