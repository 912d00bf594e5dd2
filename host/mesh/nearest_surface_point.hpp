#pragma once
// The point of a mesh's surface nearest to a point in space, exactly: a
// walk from the triangles of the nearest vertex finds it where the surface
// near the point is one sheet; where the walk stops short (a thin wall, a
// fold, long triangles beside short ones), every triangle that could be
// nearer is looked at. Any point of a triangle is within the triangle's
// longest edge of each of its corners, so a triangle nearer than the walk's
// answer has a corner within that answer plus the mesh's longest edge.
#include <memory>
#include <optional>

#include "mesh/point_cloud_tree.hpp"
#include "mesh/surface_walk.hpp"
#include "mesh/vertex_triangles.hpp"

namespace meshparticles {

class NearestSurfacePoint {
 public:
  explicit NearestSurfacePoint(const SurfaceMesh& mesh);
  // None where the mesh has no triangle.
  std::optional<SurfaceLocation> find(Vec3 p) const;

 private:
  const SurfaceMesh& mesh_;
  SurfaceWalk walk_;
  VertexTriangles around_;
  PointCloud cloud_;
  std::unique_ptr<PointCloudTree> tree_;
  double longest_edge_ = 0;
};

}  // namespace meshparticles
