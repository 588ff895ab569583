#include "support/input_errors.hpp"

#include <gtest/gtest.h>

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

void expectSceneErrorContains(std::string_view text, std::string_view part, const std::string& fileName) {
  const std::string message = sceneErrorOf(text, fileName);
  EXPECT_NE(message.find(part), std::string::npos) << "no '" << part << "' in: " << message;
}

}  // namespace lancer::test
