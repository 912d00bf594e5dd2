#include "correspondence/shape_records.hpp"

#include <cmath>
#include <stdexcept>

#include "common/json_text.hpp"
#include "reports/quality_report.hpp"

namespace meshparticles {

namespace {

// `value` as an index below `count`, read without wrapping (nlohmann's
// get<std::uint32_t> would take 2^32 as 0 and -5 as 4294967291).
std::size_t index_below(const nlohmann::json& value, std::size_t count, const char* what) {
  if (!value.is_number_unsigned() || value.get<std::uint64_t>() >= count) {
    throw std::invalid_argument(std::string(what) + " " + value.dump() + " of " + std::to_string(count));
  }
  return value.get<std::size_t>();
}

double finite_number(const nlohmann::json& value, const char* what) {
  const double number = value.get<double>();
  if (!std::isfinite(number)) throw std::invalid_argument(std::string(what) + " " + value.dump());
  return number;
}

// The slack a run's weights can be off [0, 1] and their sum off 1 by:
// rounding, many orders of magnitude below any edit that moves a particle.
constexpr double kWeightSlack = 1e-9;

void check_rows(const nlohmann::json& rows, std::size_t particles) {
  if (!rows.is_array() || rows.size() != particles) {
    throw std::invalid_argument(std::to_string(rows.size()) + " rows for " + std::to_string(particles) + " particles");
  }
}

}  // namespace

void check_barycentric(const std::array<double, 3>& weights) {
  double sum = 0;
  for (const double weight : weights) {
    if (!(weight >= -kWeightSlack && weight <= 1 + kWeightSlack)) {
      throw std::invalid_argument("weight " + nlohmann::json(weight).dump() + " outside [0, 1]");
    }
    sum += weight;
  }
  if (!(std::abs(sum - 1) <= kWeightSlack)) {
    throw std::invalid_argument("weights " + nlohmann::json(weights).dump() + " that sum to " +
                                nlohmann::json(sum).dump() + ", not 1");
  }
}

void check_entry_mesh(const nlohmann::json& recorded, const std::string& mesh) {
  if (recorded != as_written(mesh)) {
    throw std::invalid_argument("an entry of mesh " + recorded.dump() + ", not " + as_written(mesh).dump());
  }
}

nlohmann::json locations_json(const std::vector<SurfaceLocation>& locations) {
  nlohmann::json rows = nlohmann::json::array();
  for (const SurfaceLocation& at : locations) {
    rows.push_back({at.triangle, at.weights[0], at.weights[1], at.weights[2], at.at.x, at.at.y, at.at.z});
  }
  return rows;
}

std::vector<SurfaceLocation> locations_from_json(const nlohmann::json& json, std::size_t triangles,
                                                 std::size_t particles) {
  check_rows(json, particles);
  std::vector<SurfaceLocation> locations;
  for (const nlohmann::json& row : json) {
    SurfaceLocation at;
    at.triangle = std::uint32_t(index_below(row.at(0), triangles, "triangle"));
    for (std::size_t k = 0; k < 3; ++k) at.weights[k] = finite_number(row.at(1 + k), "weight");
    check_barycentric(at.weights);
    at.at = {finite_number(row.at(4), "coordinate"), finite_number(row.at(5), "coordinate"),
             finite_number(row.at(6), "coordinate")};
    locations.push_back(at);
  }
  return locations;
}

// null where no start ended in another pose, or the chosen fits exactly
// (JSON has no infinity).
nlohmann::json runner_up_json(const MeshAlignment::RunnerUp& runner_up) {
  if (!std::isfinite(runner_up.rms) || !std::isfinite(runner_up.rms_ratio)) return nullptr;
  return {{"rms_ratio", runner_up.rms_ratio}, {"degrees", runner_up.degrees}, {"rms", runner_up.rms}};
}

nlohmann::json relief_json(const MeshAlignment::Relief& relief) {
  if (!relief.measured) return nullptr;
  const bool runner_up = std::isfinite(relief.runner_up);
  return {{"by", relief.canonical ? "canonical form" : "coarse fit"},
          {"agreement", relief.agreement},
          {"runner_up", runner_up ? nlohmann::json(relief.runner_up) : nlohmann::json(nullptr)},
          {"runner_up_degrees", runner_up ? nlohmann::json(relief.runner_up_degrees) : nlohmann::json(nullptr)}};
}

nlohmann::json alignment_json(const MeshAlignment& alignment) {
  const Similarity& to_common = alignment.to_common;
  nlohmann::json rotation = nlohmann::json::array();
  for (Eigen::Index i = 0; i < 9; ++i) rotation.push_back(to_common.rotation(i / 3, i % 3));
  return {{"scale", to_common.scale},
          {"rotation", rotation},
          {"translation", {to_common.translation(0), to_common.translation(1), to_common.translation(2)}},
          {"rms", alignment.rms},
          {"iterations", alignment.iterations},
          {"from_principal_axes", alignment.from_principal_axes},
          {"runner_up", runner_up_json(alignment.runner_up)},
          {"relief", relief_json(alignment.relief)}};
}

MeshAlignment alignment_from_json(const nlohmann::json& json) {
  MeshAlignment alignment;
  alignment.to_common.scale = json.at("scale").get<double>();
  const nlohmann::json& rotation = json.at("rotation");
  const nlohmann::json& translation = json.at("translation");
  for (Eigen::Index i = 0; i < 9; ++i) alignment.to_common.rotation(i / 3, i % 3) = rotation.at(std::size_t(i)).get<double>();
  for (Eigen::Index i = 0; i < 3; ++i) alignment.to_common.translation(i) = translation.at(std::size_t(i)).get<double>();
  alignment.rms = json.at("rms").get<double>();
  alignment.iterations = json.at("iterations").get<std::size_t>();
  alignment.from_principal_axes = json.at("from_principal_axes").get<bool>();
  const nlohmann::json& relief = json.at("relief");
  if (!relief.is_null()) {
    alignment.relief.measured = true;
    const std::string by = relief.at("by").get<std::string>();
    if (by != "canonical form" && by != "coarse fit") throw std::invalid_argument("a pose told by " + relief.at("by").dump());
    alignment.relief.canonical = by == "canonical form";
    alignment.relief.agreement = relief.at("agreement").get<double>();
    if (!relief.at("runner_up").is_null()) {
      alignment.relief.runner_up = relief.at("runner_up").get<double>();
      alignment.relief.runner_up_degrees = relief.at("runner_up_degrees").get<double>();
    }
  }
  const nlohmann::json& runner_up = json.at("runner_up");
  if (!runner_up.is_null()) {
    alignment.runner_up = {runner_up.at("rms_ratio").get<double>(), runner_up.at("degrees").get<double>(),
                           runner_up.at("rms").get<double>()};
  }
  return alignment;
}

nlohmann::json shape_json(const ShapeCorrespondence& shape) {
  nlohmann::json locations = nlohmann::json::array();
  for (std::size_t i = 0; i < shape.locations.size(); ++i) {
    const InputLocation& at = shape.locations[i];
    const Eigen::Index row = Eigen::Index(i);
    locations.push_back({at.corners[0], at.corners[1], at.corners[2], at.weights[0], at.weights[1], at.weights[2],
                         at.heaviest_corner(), shape.particles(row, 0), shape.particles(row, 1),
                         shape.particles(row, 2)});
  }
  return {{"mesh", shape.mesh.string()},
          {"vertices", shape.vertices},
          {"alignment", alignment_json(shape.alignment)},
          {"topology", topology_json(shape.topology)},
          {"repaired", shape.repaired},
          {"locations", locations},
          {"quality", quality_json(shape.quality)}};
}

ShapeCorrespondence shape_from_json(const nlohmann::json& json) {
  ShapeCorrespondence shape;
  shape.mesh = json.at("mesh").get<std::string>();
  shape.vertices = json.at("vertices").get<std::size_t>();
  shape.alignment = alignment_from_json(json.at("alignment"));
  shape.topology = topology_from_json(json.at("topology"));
  shape.repaired = json.at("repaired").get<std::size_t>();
  const nlohmann::json& rows = json.at("locations");
  shape.particles.resize(Eigen::Index(rows.size()), 3);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const nlohmann::json& row = rows[i];
    InputLocation at;  // column 6, its heaviest corner, follows from the weights
    for (std::size_t k = 0; k < 3; ++k) {
      at.corners[k] = row.at(k).get<VertexId>();
      at.weights[k] = row.at(3 + k).get<double>();
      shape.particles(Eigen::Index(i), Eigen::Index(k)) = row.at(7 + k).get<double>();
    }
    shape.locations.push_back(at);
  }
  shape.quality = quality_from_json(json.at("quality"), rows.size());
  return shape;
}

void check_shape_json(const nlohmann::json& json, const std::string& mesh, std::size_t vertices,
                      std::size_t particles) {
  check_entry_mesh(json.at("mesh"), mesh);
  if (json.at("vertices") != vertices) {
    throw std::invalid_argument("a mesh of " + json.at("vertices").dump() + " vertices, not " +
                                std::to_string(vertices));
  }
  topology_from_json(json.at("topology"));
  const nlohmann::json& rows = json.at("locations");
  check_rows(rows, particles);
  for (const nlohmann::json& row : rows) {
    for (std::size_t k = 0; k < 3; ++k) index_below(row.at(k), vertices, "vertex");
    index_below(row.at(6), vertices, "vertex");
    check_barycentric({finite_number(row.at(3), "weight"), finite_number(row.at(4), "weight"),
                       finite_number(row.at(5), "weight")});
    for (const std::size_t k : {7, 8, 9}) finite_number(row.at(k), "coordinate");
  }
}

nlohmann::json topology_json(const MeshTopology& topology) {
  return {{"components", topology.components},
          {"boundary_loops", topology.boundary_loops},
          {"euler_characteristic", topology.euler_characteristic},
          {"genus", topology.genus ? nlohmann::json(*topology.genus) : nlohmann::json()}};
}

MeshTopology topology_from_json(const nlohmann::json& json) {
  MeshTopology topology;
  topology.components = json.at("components").get<std::size_t>();
  topology.boundary_loops = json.at("boundary_loops").get<std::size_t>();
  topology.euler_characteristic = json.at("euler_characteristic").get<long long>();
  if (!json.at("genus").is_null()) topology.genus = json.at("genus").get<long long>();
  return topology;
}

nlohmann::json refinement_json(const JointRefinementRecord& record) {
  return {{"overlap", record.overlap},
          {"correspondence_step", record.correspondence_step},
          {"packing_spacing", record.packing_spacing},
          {"packing_correspondence_step", record.packing_correspondence_step},
          {"packing_rounds", record.packing_rounds},
          {"packing_released", record.packing_released},
          {"packing_undone", record.packing_undone},
          {"evening_kept", record.evening_kept},
          {"gap_sweeps", record.gap_sweeps},
          {"hole_swaps", record.hole_swaps}};
}

JointRefinementRecord refinement_from_json(const nlohmann::json& json) {
  JointRefinementRecord record;
  json.at("overlap").get_to(record.overlap);
  json.at("correspondence_step").get_to(record.correspondence_step);
  json.at("packing_spacing").get_to(record.packing_spacing);
  json.at("packing_correspondence_step").get_to(record.packing_correspondence_step);
  record.packing_rounds = json.at("packing_rounds").get<std::size_t>();
  record.packing_released = json.at("packing_released").get<std::size_t>();
  record.packing_undone = json.value("packing_undone", false);
  json.at("evening_kept").get_to(record.evening_kept);
  json.at("gap_sweeps").get_to(record.gap_sweeps);
  json.at("hole_swaps").get_to(record.hole_swaps);
  return record;
}

}  // namespace meshparticles
