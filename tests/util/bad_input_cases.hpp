// The cases of the bad-input catalogue (bad_input_catalogue_badinput_test.cpp runs them and keeps
// docs/bad_input.md's table): each is a class of bad input given to the real CLI and what must hold
// after it fails.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "support/files.hpp"

namespace lancer::bad_input {

// The files of one case live in a scratch folder; commands run inside it so messages show short
// relative paths.
using Scratch = test::ScratchFolder;

struct Case {
  std::string id;     // the test's name: BadInputCatalogue/Row.PrintsItsMessage/<id>
  std::string what;   // the class of bad input, for the table
  std::string input;  // what was given, for the table
  std::function<void(const Scratch&)> setUp;
  std::string command;                        // shell command in the scratch folder; LANCER is the CLI
  std::function<void(const Scratch&)> check;  // what must hold afterwards (may be empty)
};

// Every case, in the table's order.
std::vector<Case> catalogue();

}  // namespace lancer::bad_input
