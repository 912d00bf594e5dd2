#pragma once
// The cases `bench` and `bench --quality` measure: committed meshes by name,
// each at a particle count, with every backend checked (sizes from the
// tuning file) before any distance is computed, and then visited one mesh's
// distance table at a time.
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "backends/backend_factory.hpp"
#include "geodesics/distance_cache.hpp"
#include "particles/particle_backend.hpp"

namespace meshparticles {

struct CaseRequest {
  std::string mesh;  // a committed mesh's name: sphere, torus, atrium, patch
  std::size_t particles = 0;
};

// The paper's Tables 1 and 2: sphere 128..1024, torus 128..512, atrium 256..1024.
std::vector<CaseRequest> paper_cases();
// Each committed mesh at its largest paper case, and the patch (a boundary).
std::vector<CaseRequest> quality_cases();

struct BenchRequest {
  std::vector<CaseRequest> cases;
  std::vector<std::string> backends;  // one row each
  std::string device;
  std::filesystem::path meshes_dir = "meshes";
  std::optional<std::filesystem::path> tuning_file;
  GeodesicsRequest geodesics;
  bool quiet = false;
};

struct PlannedCase {
  CaseRequest request;
  std::shared_ptr<const SurfaceMesh> mesh;
  std::vector<CheckedBackend> backends;  // in the order of BenchRequest::backends
};

struct BenchPlan {
  BenchRequest request;
  std::vector<PlannedCase> cases;
  std::string device_name = kHostDevice;  // the device of the device rows
};

// Loads each mesh once (meshes_dir/NAME.off, else the built-in generator's)
// and checks every backend for every case. Throws UserError for an unknown
// mesh, n above its vertices, or a backend that cannot run.
BenchPlan plan_bench(const BenchRequest& request);

// Called once per case with its distances; `on_row` before each row, for
// the progress line.
using CaseMeasurement = std::function<void(const PlannedCase& planned, const DistanceStore& distances,
                                           const std::function<void(const std::string&)>& on_row)>;

// Visits every case, computing (or loading) one mesh's distances at a time,
// with one progress line counting `rows_per_case` rows per case.
void for_each_case(const BenchPlan& plan, std::size_t rows_per_case, const CaseMeasurement& measure);

}  // namespace meshparticles
