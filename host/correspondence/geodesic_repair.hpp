#pragma once
// Particles the transfer carried to the wrong part of a shape, put back by
// their geodesic distances to the particles it carried right. A limb turned
// at a joint (an arm raised overhead) is where no closest-point fit follows:
// the template's arm settles on the shape's torso. But bending at a joint
// keeps distances along the surface nearly as they were, so a particle's
// geodesic distances to the others tell where it belongs: on the template,
// particle i lies at distances d_T(i, a) from the anchors a; on the shape,
// the right place for it lies at those same distances from the anchors'
// places. Anchors are particles whose own distances the transfer kept;
// a particle whose distances it did not keep moves to the shape vertex
// whose distances to the anchors fit the template's best (least squares).
// Distances are at unit area, so that shapes of any size compare.
#include <cstddef>
#include <vector>

#include "mesh/surface_location.hpp"
#include "mesh/surface_mesh.hpp"

namespace meshparticles {

// The template's side, computed once for every shape: the anchors (every
// particle, or an even subset of kMostAnchors), and the geodesic distance
// from each anchor to each particle.
struct TemplateGeodesics {
  std::vector<std::size_t> anchors;         // particle indices
  std::vector<std::vector<double>> between;  // [anchor][particle], at unit area
};

inline constexpr std::size_t kMostAnchors = 96;

TemplateGeodesics template_geodesics(const SurfaceMesh& mesh, const std::vector<SurfaceLocation>& particles);

struct GeodesicRepair {
  std::size_t moved = 0;     // particles put back
  std::size_t anchors = 0;   // the anchors trusted in the last round
  double inconsistency = 0;  // the median particle's, after (unit area)
};

// Moves `particles` (on `mesh`, row i the template's particle i) whose
// distances the transfer did not keep. Deterministic; reads nothing shared.
GeodesicRepair repair_by_geodesics(const TemplateGeodesics& reference, const SurfaceMesh& mesh,
                                   std::vector<SurfaceLocation>& particles);

}  // namespace meshparticles
