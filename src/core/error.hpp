#pragma once
// Error types. Bad input is a normal event for a tool that reads user folders: it becomes an
// InputError naming the file (and line), which the CLI turns into exit code 2 with that message.
#include <stdexcept>
#include <string>

namespace dynanav {

enum ExitCode : int { kExitOk = 0, kExitBadInput = 2, kExitNotInitialised = 3 };

class InputError : public std::runtime_error {
 public:
  /// `where` is a file path, optionally with ":line"; `what` says what is wrong.
  InputError(const std::string& where, const std::string& what)
      : std::runtime_error(where.empty() ? what : where + ": " + what) {}
};

/// A configuration problem (unknown key, wrong type, value out of range).
class ConfigError : public InputError {
 public:
  using InputError::InputError;
};

}  // namespace dynanav
