#pragma once
// An error the user can act on (bad input, bad arguments, missing runtime):
// the command-line layer prints its message as one line and exits with
// exit_code(). Anything else that escapes is a bug and exits with 1.
#include <stdexcept>
#include <string>

namespace meshparticles {

class UserError : public std::runtime_error {
 public:
  explicit UserError(const std::string& message, int exit_code = 2)
      : std::runtime_error(message), exit_code_(exit_code) {}
  int exit_code() const { return exit_code_; }

 private:
  int exit_code_;
};

}  // namespace meshparticles
