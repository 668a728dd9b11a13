#pragma once

#include <stdexcept>
#include <string>
#include <utility>

namespace sedem {

// Input that cannot be used. The message names where it came from (file and line, or
// `--set`), the key, the value and what is allowed; nothing runs on it. Every stage that
// checks its own setup throws it, so that one catch serves a whole command.
struct SceneError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A stage's own rule broken by its setup: the key at fault and what is wrong with its value.
// The scene's checks catch it and add where the key was given and its value (SceneError).
struct SetupProblem : std::runtime_error {
  SetupProblem(std::string key_, const std::string& what)
      : std::runtime_error(key_ + " " + what), key(std::move(key_)), problem(what) {}
  std::string key, problem;
};

}  // namespace sedem
