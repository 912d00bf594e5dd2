#include "cli/run_options.hpp"

#include "common/overloaded.hpp"
#include "options/number_options.hpp"
#include "options/run_option_table.hpp"

namespace meshparticles {

namespace {

// A word or a path, stored as given; a word among its row's words when it has some.
template <typename Value>
CLI::Option* add_text_option(CLI::App& command, const RunOptionSpec& row, std::optional<Value>& target) {
  CLI::Option* option = command.add_option_function<std::string>(
      row.command_line_names(), [&target](const std::string& text) { target = Value(text); }, row.help);
  if (!row.words.empty()) option->check(CLI::IsMember(row.words));
  return option;
}

CLI::Option* add_table_option(CLI::App& command, const RunOptionSpec& row, RunOptionValues& values) {
  const std::string names = row.command_line_names();
  return std::visit(
      Overloaded{
          [&](WholeField field) { return add_whole_number_option(command, names, values.*field, row.range, row.help); },
          [&](PositiveField field) { return add_positive_number_option(command, names, values.*field, row.help); },
          [&](WordField field) { return add_text_option(command, row, values.*field); },
          [&](PathField field) { return add_text_option(command, row, values.*field); },
          [&](FlagField field) { return command.add_flag(names, values.*field, row.help); },
      },
      row.field);
}

}  // namespace

void add_run_options(CLI::App& command, RunOptionValues& options) {
  for (const RunOptionSpec& row : run_option_table()) {
    CLI::Option* option = add_table_option(command, row, options);
    if (!row.shown_default.empty()) option->default_str(row.shown_default);
  }
}

}  // namespace meshparticles
