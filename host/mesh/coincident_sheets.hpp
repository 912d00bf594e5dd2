#pragma once
// Sheets of a surface at one place: triangles whose three corners lie
// exactly where another triangle's do, through other vertices (two copies of
// a disk, one flipped; a closed shell written twice). A point there is on
// every sheet, so a list of points - a particle file - cannot say which
// sheet each is on: `quality` of a run's own particles measures each on one
// of them, and its figures are not the run's. mesh_checks warns of them,
// and report.json says so (reports/run_report).
#include <cstddef>
#include <string>

#include "mesh/surface_mesh.hpp"

namespace meshparticles {

struct CoincidentSheets {
  std::size_t triangles = 0;  // triangles with another at the same place
  Vec3 example{};             // the centre of one of them
};

// Exact comparison of coordinates: the copies a file holds are the same
// numbers. O(V log V + T log T).
CoincidentSheets coincident_sheets(const SurfaceMesh& mesh);

// "600 triangles lie on other triangles (coincident sheets, e.g. at 0.1 0 0):
// ..." for a warning; empty when there are none.
std::string coincident_sheets_text(const CoincidentSheets& sheets);

}  // namespace meshparticles
