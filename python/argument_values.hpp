#pragma once
// Python values checked as the command line checks its options' text
// (options/number_options.hpp, options/option_values.hpp), and refused as the
// standard library refuses them: TypeError for a wrong type, ValueError for
// a wrong value, one line naming the keyword. Nothing is converted the way
// int() or str() would: n=2.7 is refused, not truncated to 2.
#include <cstdint>
#include <filesystem>
#include <string>

#include <pybind11/pybind11.h>

#include "options/number_options.hpp"

namespace meshparticles::python {

// An int, or what stands for one (__index__: NumPy's integers), within
// `range`. bool, float and str are refused: True is not a count, and int()
// would truncate 2.7 and parse "3".
std::uint64_t whole_number(pybind11::handle value, const std::string& name, WholeRange range);

// An int or a float (or what converts by __float__), not bool or str.
double real_number(pybind11::handle value, const std::string& name);

// A real number, finite and above 0 (what --sigma, --cutoff, ... take).
double positive_number(pybind11::handle value, const std::string& name);

// True or False (NumPy's bool too), nothing that merely converts to one.
bool flag(pybind11::handle value, const std::string& name);

// A str, not empty (the command line refuses empty values too; None asks
// for the default) and without NUL.
std::string word(pybind11::handle value, const std::string& name);

// A path as open() takes one: str (a name that is not UTF-8 comes back
// from its surrogate escapes, as os.fsencode does), bytes or os.PathLike;
// not empty, no NUL byte (ValueError, as open() raises), and within Linux's
// limits on a path's length.
std::filesystem::path path_argument(pybind11::handle value, const std::string& name);

// The other way: a path's bytes as os.fsdecode gives them back (a name
// that is not UTF-8 in surrogate escapes, so that it opens the same file).
pybind11::str path_text(const std::string& native);

}  // namespace meshparticles::python
