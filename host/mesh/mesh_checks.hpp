#pragma once
// What OpenMesh lets through, caught here: counts that disagree with the
// header, non-finite coordinates, bad or repeated face indices, non-manifold
// edges and vertices. Tolerated with a warning: polygons (triangulated),
// degenerate triangles, unreferenced vertices (dropped, ids remembered).
#include <string>
#include <vector>

#include "mesh/polygon_soup.hpp"
#include "mesh/surface_mesh.hpp"

namespace meshparticles {

// Throws UserError("LABEL: problem") for the first fatal problem.
SurfaceMesh build_checked_mesh(const PolygonSoup& soup, const std::string& label,
                               std::vector<std::string>& warnings);

}  // namespace meshparticles
