#pragma once
// What kind of surface a mesh is, up to deformation: its components, the
// loops of its boundary and its genus. Shapes of one population share it;
// a correspondence between a sphere and a torus maps parts that are not
// there, so `correspond` compares each shape's with the template's.
#include <optional>
#include <string>

#include "mesh/surface_mesh.hpp"

namespace meshparticles {

struct MeshTopology {
  std::size_t components = 0;
  std::size_t boundary_loops = 0;  // closed chains of edges in one triangle each
  long long euler_characteristic = 0;  // vertices - edges + triangles
  // The sum of the components' genera, from 2 * components - euler - loops
  // = 2 * genus; absent where that is no whole number of at least 0 (a
  // non-manifold mesh).
  std::optional<long long> genus;

  bool operator==(const MeshTopology&) const = default;
};

MeshTopology mesh_topology(const SurfaceMesh& mesh);

// "1 component, genus 0, no boundary"; "2 components, genus 1, 3 boundary loops".
std::string describe(const MeshTopology& topology);

}  // namespace meshparticles
