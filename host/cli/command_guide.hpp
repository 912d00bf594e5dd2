#pragma once
// What a new user meets before any command runs: the short usage of a bare
// `meshparticles`, the answer to a misspelt command, and the bash completion
// script, all derived from the commands registered on the app so they cannot
// go stale.
#include <CLI/CLI.hpp>
#include <optional>
#include <string>

namespace meshparticles {

// "usage: meshparticles COMMAND ..." and one line per command.
std::string short_usage(const CLI::App& app);

// When WORD (the first argument) is neither an option nor a command: the
// one-line error naming it, the closest command and the list of commands.
std::optional<std::string> unknown_command_error(const CLI::App& app, const std::string& word);

// A bash script completing command names and each command's options.
std::string bash_completion_script(const CLI::App& app);

// `meshparticles completion bash`.
void add_completion_command(CLI::App& app);

}  // namespace meshparticles
