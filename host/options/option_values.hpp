#pragma once
// What no option or positional takes, checked once for every command: an
// empty value (never a way to ask for a default), an empty element of a
// comma-separated list ("a,,b"), and a path the system could not hold
// (refused while parsing, before any work, not after it).
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace meshparticles {

// "a,b" -> {"a", "b"}; an empty element is refused: UserError("LABEL: ...").
std::vector<std::string> split_list(const std::string& text, const std::string& label);

// A comma-separated list of names (may be given more than once), each one
// of `allowed` when that is not empty; the list given replaces the default.
CLI::Option* add_name_list_option(CLI::App& command, const std::string& names, std::vector<std::string>& target,
                                  const std::vector<std::string>& allowed, const std::string& help);

// Why the system could not hold `path` (longer than PATH_MAX, or a part
// longer than NAME_MAX), or "" when it could.
std::string unusable_path_reason(const std::string& path);

// Adds the checks to every option that takes a value, in `app` and all its
// subcommands; path checks to the options that name files or folders.
void refuse_unusable_values(CLI::App& app);

}  // namespace meshparticles
