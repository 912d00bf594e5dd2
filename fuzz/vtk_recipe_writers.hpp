#pragma once
// A recipe written out as a file: legacy .vtk (ASCII or BINARY, 4.2 or
// 5.1, POLYDATA or UNSTRUCTURED_GRID) or XML .vtp (ascii, inline base64,
// appended raw or base64; zlib or not; UInt32 or UInt64 headers; either
// byte order), with the recipe's tweaks and byte edits applied.
#include <string>

#include "mesh/polygon_soup.hpp"
#include "vtk_recipe.hpp"

namespace meshparticles::fuzzing {

std::string write_legacy_vtk(const Recipe& recipe);
std::string write_vtp(const Recipe& recipe);

// The file the recipe describes, in its encoding, byte edits applied.
std::string write_recipe_file(const Recipe& recipe);

// What a reader must make of the file of a recipe without tweaks: every
// piece's points in order, then its polygons and its strips' triangles
// (every other one turned, joins skipped), indices shifted past the
// earlier pieces' points.
PolygonSoup expected_soup(const Recipe& recipe);

}  // namespace meshparticles::fuzzing
