#pragma once
// The keyword options of run(), batch(), quality() and compare() taken by
// the rows of the run options' table (options/run_option_table.hpp): its
// keyword (`--rebuild-every` is rebuild_every=), checked as its row says,
// into RunOptionValues, which the command line's own functions resolve.
#include <initializer_list>

#include "keyword_options.hpp"
#include "options/run_option_values.hpp"

namespace meshparticles::python {

// The rows named (the command line's names) taken from `options`.
RunOptionValues take_run_options(KeywordOptions& options, std::initializer_list<const char*> names);

// Every row that has a keyword: every option of `meshparticles run` but the
// mesh, --out and --strict (read_mesh takes strict=).
RunOptionValues take_run_options(KeywordOptions& options);

}  // namespace meshparticles::python
