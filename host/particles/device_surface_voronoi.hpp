#pragma once
// The geodesic Voronoi diagram of points on a surface (surface_voronoi.hpp)
// on an OpenCL device: kernels/surface_voronoi.cl, the rounds of
// surface_voronoi_rounds, one work-item per vertex, from the same seeds.
// The host's rounds are its oracle: each vertex's step is written once
// (kernels/surface_voronoi_round.h) and each round reads the last one's
// buffers only, so the two give the same bits whatever the device and its
// scheduling. Fast marching's diagram (surface_voronoi) agrees with both
// to the methods' accuracy, not bit for bit (docs/GEODESICS.md, "What runs
// where").
//
// The mesh's buffers stay on the device for the object's life: the evening
// step asks for a diagram every sweep on the same mesh.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "mesh/surface_location.hpp"
#include "mesh/surface_mesh.hpp"
#include "opencl/device_discovery.hpp"
#include "particles/surface_voronoi.hpp"
#include "particles/voronoi_stencils.hpp"

namespace meshparticles {

// Throws UserError when the device's diagram of a closed mesh of `vertices`
// vertices would not fit `device`: what a plan checks before the mesh is
// built (the constructor checks the mesh's own sizes).
void check_device_voronoi_fits(const DeviceDescription& device, std::uint64_t vertices);

class DeviceSurfaceVoronoi {
 public:
  struct Statistics {
    std::size_t diagrams = 0;  // anew or updated
    std::size_t rounds = 0;    // rounds that changed something, over all diagrams
    std::size_t batches = 0;   // host waits: one per batch of rounds
    double seconds = 0;        // everything: seeding, uploads, rounds, reads
  };

  // Throws UserError, before any buffer is made, when the mesh's buffers
  // would not fit `device`.
  DeviceSurfaceVoronoi(const SurfaceMesh& mesh, const DeviceDescription& device);

  // The diagram of `points` (points of the mesh's triangles), as
  // surface_voronoi gives it.
  SurfaceVoronoi diagram(std::span<const SurfaceLocation> points);

  // `cells`, the diagram of `points` before those flagged in `moved` moved,
  // brought up to date as update_surface_voronoi does on the host: their
  // regions emptied, their new corners seeded (reseed_moved_points), and
  // rounds from those corners and the rims. As near the host's diagram as
  // one anew (nearer, measured), not its bits: rounds go by edges, not by
  // distance, so anew a front that crosses a vertex later taken by a nearer
  // point leaves the vertices beyond it lower than that point's corners
  // give, where the update starts with the unmoved regions settled.
  void update(std::span<const SurfaceLocation> points, std::span<const char> moved, SurfaceVoronoi& cells);

  const std::string& device_name() const { return device_name_; }
  const Statistics& statistics() const { return statistics_; }

 private:
  // Rounds from `voronoi` until none changes anything, the vertices in
  // `changed` taken as changed just before the first.
  void converge(std::span<const VertexId> changed, SurfaceVoronoi& voronoi);

  const SurfaceMesh& mesh_;
  std::string device_name_;
  std::size_t work_group_size_ = 0;
  cl::Context context_;
  cl::CommandQueue queue_;
  cl::Kernel kernel_;
  cl::Buffer ring_offsets_, ring_neighbors_, edge_lengths_, pull_offsets_, pulls_, dependent_offsets_, dependents_;
  cl::Buffer states_[2], dirty_[3], round_changed_;
  VoronoiStencils stencils_;  // on the host: the dependents only, what marks round 0
  std::vector<cl_uchar> dirty_start_;
  Statistics statistics_;
};

}  // namespace meshparticles
