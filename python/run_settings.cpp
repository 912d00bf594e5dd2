#include "run_settings.hpp"

#include "common/overloaded.hpp"
#include "options/run_option_table.hpp"

namespace meshparticles::python {

namespace {

void take_row(KeywordOptions& options, const RunOptionSpec& row, RunOptionValues& values) {
  const char* keyword = row.keyword.c_str();
  std::visit(Overloaded{
                 [&](WholeField field) { values.*field = options.take_whole(keyword, row.range); },
                 [&](PositiveField field) { values.*field = options.take_positive(keyword); },
                 [&](WordField field) { values.*field = options.take_word(keyword); },
                 [&](PathField field) { values.*field = options.take_path(keyword); },
                 [&](FlagField field) { values.*field = options.take_flag(keyword).value_or(false); },
             },
             row.field);
}

}  // namespace

RunOptionValues take_run_options(KeywordOptions& options, std::initializer_list<const char*> names) {
  RunOptionValues values;
  for (const char* name : names) take_row(options, run_option(name), values);
  return values;
}

RunOptionValues take_run_options(KeywordOptions& options) {
  RunOptionValues values;
  for (const RunOptionSpec& row : run_option_table()) {
    if (!row.keyword.empty()) take_row(options, row, values);
  }
  return values;
}

}  // namespace meshparticles::python
