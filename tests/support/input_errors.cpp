#include "support/input_errors.hpp"

#include "lancer/scene/scene_loader.hpp"
#include "lancer/util/input_error.hpp"

namespace lancer::test {

std::string messageOf(const std::function<void()>& action) {
  try {
    action();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no InputError)";
}

std::string sceneErrorOf(std::string_view text, const std::string& fileName) {
  return messageOf([&] { parseScene(text, fileName); });
}

}  // namespace lancer::test
