#pragma once
// What a reader hands on, checked before anything uses it. Refused: no
// vertices or faces, non-finite coordinates, bad face indices, no area (every
// triangle degenerate) or an area that overflows a double. Tolerated with
// one warning line per kind: polygons (fan-triangulated), degenerate
// triangles, unreferenced vertices (dropped, input ids remembered),
// inconsistent orientation, and the non-manifold cases real scans have:
// edges in more than two triangles and vertices where separate fans meet
// (kept as they are), repeated triangles (dropped), and triangles lying on
// others through other vertices (coincident sheets: mesh/coincident_sheets).
#include <string>
#include <vector>

#include "mesh/polygon_soup.hpp"
#include "mesh/surface_mesh.hpp"

namespace meshparticles {

struct MeshReadOptions {
  // Refuse non-manifold edges and vertices and repeated triangles, instead of
  // keeping (or dropping) them with a warning.
  bool strict = false;
};

// Throws UserError("LABEL: problem") for the first fatal problem.
SurfaceMesh build_checked_mesh(const PolygonSoup& soup, const std::string& label, std::vector<std::string>& warnings,
                               const MeshReadOptions& options = {});

}  // namespace meshparticles
