#pragma once
// What an exception means for the user, in one place: the command line's
// exit code and message for a whole command (cli/main.cpp), and a batch's
// status for one mesh (a refusal the user can act on, or a failure).
#include <exception>
#include <string>

namespace meshparticles {

struct Failure {
  int exit_code = 1;     // 2: bad input or arguments; 3: no OpenCL runtime; 1: a bug
  bool internal = true;  // an unexpected exception: "internal error" rather than "error"
  std::string message;   // one line
};

// `error` (UserError, an OpenCL error, out of memory or any other) described.
Failure describe_failure(const std::exception_ptr& error);

}  // namespace meshparticles
