#include "options/option_values.hpp"

#include <climits>
#include <filesystem>

#include "common/user_error.hpp"

namespace meshparticles {

namespace {

// The options and positionals whose values are paths.
const char* const kPathOptions[] = {"mesh",   "particles",     "inputs",      "--out",       "--out-dir",
                                    "--csv",  "--json",        "--tuning-file", "--cache-dir", "--meshes-dir"};

bool is_path_option(const CLI::Option& option) {
  for (const char* name : kPathOptions) {
    if (option.check_name(name)) return true;
  }
  return false;
}

std::string non_empty(const std::string& value) {
  return value.empty() ? "an empty value is not allowed (leave the option out for its default)" : "";
}

void add_checks(CLI::App& command) {
  for (CLI::Option* option : command.get_options()) {
    if (option->get_type_size() == 0) continue;  // a flag
    option->check(CLI::Validator(non_empty, "", "NONEMPTY"));
    if (is_path_option(*option)) option->check(CLI::Validator(unusable_path_reason, "", "PATH"));
  }
  for (CLI::App* subcommand : command.get_subcommands([](CLI::App*) { return true; })) add_checks(*subcommand);
}

}  // namespace

// Linux's limits (PATH_MAX, NAME_MAX): a longer path fails at the first
// open or mkdir, which may come after minutes of work.
std::string unusable_path_reason(const std::string& path) {
  if (path.size() >= PATH_MAX) {
    return "the path is " + std::to_string(path.size()) + " bytes, more than the " + std::to_string(PATH_MAX - 1) +
           " a path may have";
  }
  for (const auto& part : std::filesystem::path(path)) {
    if (part.native().size() > NAME_MAX) {
      return "a part of the path is " + std::to_string(part.native().size()) + " bytes, more than the " +
             std::to_string(NAME_MAX) + " a file name may have";
    }
  }
  return "";
}

std::vector<std::string> split_list(const std::string& text, const std::string& label) {
  std::vector<std::string> elements;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = text.find(',', start);
    const std::string element = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    if (element.empty()) throw UserError(label + ": an empty element in \"" + text + "\" (a list is \"a,b,c\")");
    elements.push_back(element);
    if (comma == std::string::npos) return elements;
    start = comma + 1;
  }
}

CLI::Option* add_name_list_option(CLI::App& command, const std::string& names, std::vector<std::string>& target,
                                  const std::vector<std::string>& allowed, const std::string& help) {
  std::string defaults;
  for (const std::string& name : target) defaults += (defaults.empty() ? "" : ",") + name;
  const std::string label = names;
  CLI::Option* option = command.add_option_function<std::vector<std::string>>(
      names,
      [&target, allowed, label](const std::vector<std::string>& texts) {
        target.clear();
        for (const std::string& text : texts) {
          for (const std::string& name : split_list(text, label)) {
            if (!allowed.empty() && std::find(allowed.begin(), allowed.end(), name) == allowed.end()) {
              std::string choices;
              for (const std::string& choice : allowed) choices += (choices.empty() ? "" : ", ") + choice;
              throw UserError(label + ": '" + name + "' is not one of " + choices);
            }
            target.push_back(name);
          }
        }
      },
      help);
  option->type_name("NAME,...")->allow_extra_args(false);
  if (!defaults.empty()) option->default_str(defaults);
  return option;
}

void refuse_unusable_values(CLI::App& app) { add_checks(app); }

}  // namespace meshparticles
