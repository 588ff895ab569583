#include "support/input_errors.hpp"

#include <gtest/gtest.h>

#include "lancer/mesh/msh_reader.hpp"
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

std::string replaceOnce(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

std::string firstReaderWarning(const std::string& bytes, const std::string& name, std::size_t* fields) {
  try {
    const Mesh mesh = readMshFromMemory(bytes, name);
    EXPECT_GT(mesh.faceCount(), 0u);
    if (fields) *fields = mesh.fields.size();
    return mesh.source.warnings.empty() ? "" : mesh.source.warnings.front();
  } catch (const InputError& error) {
    ADD_FAILURE() << "the mesh did not load: " << error.what();
    return error.what();
  }
}

}  // namespace lancer::test
