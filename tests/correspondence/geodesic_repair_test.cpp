// correspondence/geodesic_repair: particles the transfer left on the wrong
// part of a shape, put back by their geodesic distances to the others.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "correspondence/geodesic_repair.hpp"
#include "fixtures/mesh_generator.hpp"
#include "mesh/vertex_triangles.hpp"

namespace meshparticles::testing {
namespace {

SurfaceLocation at_vertex(const SurfaceMesh& mesh, const VertexTriangles& around, VertexId v) {
  SurfaceLocation at;
  at.triangle = around.around(v).front();
  for (std::size_t k = 0; k < 3; ++k) at.weights[k] = mesh.triangles()[at.triangle][k] == v ? 1.0 : 0.0;
  at.at = mesh.positions()[v];
  return at;
}

// The same surface twice as large (distances compare at unit area), its
// particles where the template's are but for a few sent across it.
TEST(GeodesicRepair, ParticlesSentAcrossTheShapeComeBackAndTheRestStay) {
  const SurfaceMesh template_mesh = generate_ellipsoid_variant(4, 1500).mesh;
  std::vector<Vec3> doubled = template_mesh.positions();
  for (Vec3& p : doubled) p = 2.0 * p;
  const SurfaceMesh shape(doubled, template_mesh.triangles());
  const VertexTriangles around = vertex_triangles(template_mesh.triangles(), template_mesh.vertex_count());
  std::vector<SurfaceLocation> particles;
  std::vector<VertexId> places;
  for (VertexId v = 0; v < template_mesh.vertex_count(); v += 23) places.push_back(v);
  for (const VertexId v : places) particles.push_back(at_vertex(template_mesh, around, v));
  const TemplateGeodesics reference = template_geodesics(template_mesh, particles);
  EXPECT_EQ(reference.between.size(), reference.anchors.size());
  EXPECT_EQ(reference.between.front().size(), particles.size());

  std::vector<SurfaceLocation> carried;
  for (const VertexId v : places) carried.push_back(at_vertex(shape, around, v));
  const std::vector<std::size_t> sent = {3, 17, 30, 41, 50};
  for (const std::size_t i : sent) {
    carried[i] = at_vertex(shape, around, places[(i + places.size() / 2) % places.size()]);  // across the shape
  }
  ASSERT_GT(places.size(), sent.back());
  const GeodesicRepair repair = repair_by_geodesics(reference, shape, carried);
  EXPECT_EQ(repair.moved, sent.size());
  for (std::size_t i = 0; i < places.size(); ++i) {
    const Vec3 d = carried[i].at - shape.positions()[places[i]];
    EXPECT_LT(d.x * d.x + d.y * d.y + d.z * d.z, 1e-18) << "particle " << i;
  }
  EXPECT_LT(repair.inconsistency, 1e-3);
}

// Two particles whose distances fit one vertex best (the template's
// particle twice) are not both put on it: one takes it, the other the
// nearest fit beside it.
TEST(GeodesicRepair, NoTwoParticlesArePutOnOneVertex) {
  const SurfaceMesh mesh = generate_ellipsoid_variant(4, 1500).mesh;
  const VertexTriangles around = vertex_triangles(mesh.triangles(), mesh.vertex_count());
  std::vector<VertexId> places;
  for (VertexId v = 0; v < mesh.vertex_count(); v += 23) places.push_back(v);
  places.push_back(places[10]);
  std::vector<SurfaceLocation> particles;
  for (const VertexId v : places) particles.push_back(at_vertex(mesh, around, v));
  const TemplateGeodesics reference = template_geodesics(mesh, particles);
  std::vector<SurfaceLocation> carried = particles;
  const std::size_t twin = places.size() - 1;
  for (const std::size_t i : {std::size_t(10), twin}) {
    carried[i] = at_vertex(mesh, around, places[(i + places.size() / 2) % places.size()]);  // across the shape
  }
  const GeodesicRepair repair = repair_by_geodesics(reference, mesh, carried);
  EXPECT_EQ(repair.moved, 2u);
  const Vec3 d = carried[10].at - carried[twin].at;
  EXPECT_GT(d.x * d.x + d.y * d.y + d.z * d.z, 0) << "stacked";
  for (const std::size_t i : {std::size_t(10), twin}) {
    const Vec3 off = carried[i].at - mesh.positions()[places[10]];
    EXPECT_LT(std::sqrt(off.x * off.x + off.y * off.y + off.z * off.z), 0.05 * std::sqrt(mesh.area())) << i;
  }
}

// A shape whose particles all lie right: none moves.
TEST(GeodesicRepair, ParticlesInPlaceStay) {
  const SurfaceMesh mesh = generate_ellipsoid_variant(5, 1200).mesh;
  const VertexTriangles around = vertex_triangles(mesh.triangles(), mesh.vertex_count());
  std::vector<SurfaceLocation> particles;
  for (VertexId v = 5; v < mesh.vertex_count(); v += 31) particles.push_back(at_vertex(mesh, around, v));
  const TemplateGeodesics reference = template_geodesics(mesh, particles);
  std::vector<SurfaceLocation> carried = particles;
  EXPECT_EQ(repair_by_geodesics(reference, mesh, carried).moved, 0u);
  for (std::size_t i = 0; i < particles.size(); ++i) EXPECT_EQ(carried[i].triangle, particles[i].triangle);
}

}  // namespace
}  // namespace meshparticles::testing
