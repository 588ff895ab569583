// The message of the InputError a call throws, for the tests that check what the user is told
// (every bad-input path has a test of its message, not just of the failure).
#pragma once

#include <functional>
#include <string>
#include <string_view>

namespace lancer::test {

// What `action` throws as an InputError, or "(no InputError)" when it throws none.
std::string messageOf(const std::function<void()>& action);

// The message of parseScene(text, fileName), as a scene file of that name would give it.
std::string sceneErrorOf(std::string_view text, const std::string& fileName = "scene.toml");

// Adds a gtest failure, with the whole message, unless sceneErrorOf(text, fileName) contains `part`.
void expectSceneErrorContains(std::string_view text, std::string_view part,
                              const std::string& fileName = "scene.toml");

// `text` with its first `from` replaced by `to`; a gtest failure when `from` is not in it (the edit
// of a fixture that no longer matches is a broken test, not a pass).
std::string replaceOnce(std::string text, const std::string& from, const std::string& to);

// The .msh reader's first warning for `bytes` read as the file `name` ("name:line:col: warning: ..."),
// or "" when it gave none; a gtest failure unless the mesh loads with faces. fields: how many fields
// it kept.
std::string firstReaderWarning(const std::string& bytes, const std::string& name,
                               std::size_t* fields = nullptr);

}  // namespace lancer::test
