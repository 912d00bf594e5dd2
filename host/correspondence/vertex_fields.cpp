#include "correspondence/vertex_fields.hpp"

namespace meshparticles {

PointSet vertex_normals(const std::vector<Triangle>& triangles, const PointSet& points) {
  PointSet normals = PointSet::Zero(points.rows(), 3);
  for (const Triangle& t : triangles) {
    const Eigen::RowVector3d a = points.row(Eigen::Index(t[0]));
    const Eigen::RowVector3d n = (points.row(Eigen::Index(t[1])) - a).cross(points.row(Eigen::Index(t[2])) - a);
    for (const VertexId v : t) normals.row(Eigen::Index(v)) += n;
  }
  for (Eigen::Index v = 0; v < normals.rows(); ++v) {
    const double length = normals.row(v).norm();
    if (length > 0) normals.row(v) /= length;
  }
  return normals;
}

std::vector<Vec3> positions_of(const PointSet& points) {
  std::vector<Vec3> positions(std::size_t(points.rows()));
  for (Eigen::Index i = 0; i < points.rows(); ++i) positions[std::size_t(i)] = {points(i, 0), points(i, 1), points(i, 2)};
  return positions;
}

void smooth_over(const SurfaceMesh& mesh, PointSet& field, int rounds) {
  PointSet next(field.rows(), 3);
  for (int round = 0; round < rounds; ++round) {
    for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
      Eigen::RowVector3d sum = field.row(Eigen::Index(v));
      for (const VertexId w : mesh.one_ring(v)) sum += field.row(Eigen::Index(w));
      next.row(Eigen::Index(v)) = sum / double(mesh.valence(v) + 1);
    }
    field.swap(next);
  }
}

double signed_volume(const std::vector<Triangle>& triangles, const PointSet& points) {
  double sum = 0;
  for (const Triangle& t : triangles) {
    const Eigen::Vector3d a = points.row(t[0]), b = points.row(t[1]), c = points.row(t[2]);
    sum += a.dot(b.cross(c));
  }
  return sum;
}

}  // namespace meshparticles
