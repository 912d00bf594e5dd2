#include "cli/command_guide.hpp"

#include <algorithm>
#include <iostream>
#include <memory>
#include <sstream>
#include <vector>

namespace meshparticles {

namespace {

std::vector<const CLI::App*> commands_of(const CLI::App& app) {
  return app.get_subcommands([](const CLI::App*) { return true; });
}

std::string command_list(const CLI::App& app) {
  std::string list;
  for (const CLI::App* command : commands_of(app)) list += (list.empty() ? "" : ", ") + command->get_name();
  return list;
}

// Edits (insert, delete, substitute) between A and B.
std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

// Every spelling of each option of COMMAND that takes a name (--long, -s).
std::string option_words(const CLI::App& command) {
  std::string words;
  for (const CLI::Option* option : command.get_options()) {
    for (const std::string& name : option->get_lnames()) words += " --" + name;
    for (const std::string& name : option->get_snames()) words += " -" + name;
  }
  return words.empty() ? words : words.substr(1);
}

// A command's description up to its first colon or parenthesis: one short line.
std::string headline(const std::string& description) {
  const std::string head = description.substr(0, std::min(description.find(':'), description.find(" (")));
  return head.substr(0, head.find_last_not_of(' ') + 1);
}

}  // namespace

std::string short_usage(const CLI::App& app) {
  std::ostringstream usage;
  usage << "usage: meshparticles COMMAND [options]   (meshparticles COMMAND --help for its options)\n\ncommands:\n";
  std::size_t width = 0;
  for (const CLI::App* command : commands_of(app)) width = std::max(width, command->get_name().size());
  for (const CLI::App* command : commands_of(app)) {
    usage << "  " << command->get_name() << std::string(width + 2 - command->get_name().size(), ' ')
          << headline(command->get_description()) << "\n";
  }
  usage << "\nexample: meshparticles run MESH -n 1024 --out DIR   (--version, --help)\n";
  return usage.str();
}

std::optional<std::string> unknown_command_error(const CLI::App& app, const std::string& word) {
  if (word.empty() || word.front() == '-') return std::nullopt;
  const std::vector<const CLI::App*> commands = commands_of(app);
  const CLI::App* closest = nullptr;
  std::size_t closest_distance = 0;
  for (const CLI::App* command : commands) {
    if (command->get_name() == word) return std::nullopt;
    const std::size_t distance = edit_distance(word, command->get_name());
    if (!closest || distance < closest_distance) closest = command, closest_distance = distance;
  }
  std::string message = "unknown command '" + word + "'";
  // Two edits or a third of the word: a typo, not a different word.
  if (closest && closest_distance <= std::max<std::size_t>(2, word.size() / 3)) {
    message += "; did you mean '" + closest->get_name() + "'?";
  }
  return message + " (commands: " + command_list(app) + ")";
}

std::string bash_completion_script(const CLI::App& app) {
  std::ostringstream script;
  script << "# bash completion for meshparticles: source <(meshparticles completion bash)\n"
            "_meshparticles() {\n"
            "  local cur=\"${COMP_WORDS[COMP_CWORD]}\" words\n"
            "  if ((COMP_CWORD == 1)); then\n"
            "    words=\"";
  for (const CLI::App* command : commands_of(app)) script << command->get_name() << " ";
  script << option_words(app) << "\"\n"
            "  else\n"
            "    case \"${COMP_WORDS[1]}\" in\n";
  for (const CLI::App* command : commands_of(app)) {
    script << "      " << command->get_name() << ") words=\"" << option_words(*command) << "\" ;;\n";
  }
  script << "      *) words=\"\" ;;\n"
            "    esac\n"
            "    # Anything but an option name is left to bash's file completion (-o default).\n"
            "    [[ \"$cur\" == -* ]] || return 0\n"
            "  fi\n"
            "  COMPREPLY=($(compgen -W \"$words\" -- \"$cur\"))\n"
            "}\n"
            "complete -o default -F _meshparticles meshparticles\n";
  return script.str();
}

void add_completion_command(CLI::App& app) {
  CLI::App* command = app.add_subcommand(
      "completion", "Print a shell completion script (bash: source <(meshparticles completion bash))");
  auto shell = std::make_shared<std::string>();
  command->add_option("shell", *shell, "The shell")->required()->check(CLI::IsMember({"bash"}));
  command->callback([&app, shell] { std::cout << bash_completion_script(app); });
}

}  // namespace meshparticles
