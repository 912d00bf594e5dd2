// What a run leaves behind: every file, complete, with input vertex ids and
// the report's promised keys - from the real pipeline, as `run` calls it.
#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <openssl/evp.h>
#include <unistd.h>

#include <cstring>

#include "common/user_error.hpp"
#include "common/version.hpp"
#include "mesh/io/mesh_reader.hpp"
#include "particle_test_support.hpp"
#include "particles/particle_file.hpp"
#include "pipeline/run_pipeline.hpp"
#include "reports/particle_locations.hpp"
#include "reports/run_outputs.hpp"
#include "reports/run_report.hpp"
#include "test_files.hpp"

namespace meshparticles::testing {
namespace {


// The Float32 values of the first base64 DataArray in a .vtp after `after`.
std::vector<float> first_float_array(const std::string& xml, const std::string& after) {
  const std::size_t start = xml.find('>', xml.find("<DataArray", xml.find(after))) + 1;
  const std::string text = xml.substr(start, xml.find('<', start) - start);
  std::vector<unsigned char> bytes(text.size() / 4 * 3 + 3);
  const int decoded = EVP_DecodeBlock(bytes.data(), reinterpret_cast<const unsigned char*>(text.data()), int(text.size()));
  std::uint64_t count = 0;
  if (decoded < 8) return {};
  std::memcpy(&count, bytes.data(), 8);
  std::vector<float> values(count / sizeof(float));
  std::memcpy(values.data(), bytes.data() + 8, count);
  return values;
}

TEST(RunOutputs, WritesParticlesCsvAndReport) {
  std::vector<std::string> warnings;
  // Vertices 0 and 3 of this file have no face: the surface's ids differ from the file's.
  const SurfaceMesh mesh = read_mesh(std::string(TEST_DATA_DIR) + "/unreferenced_vertices.off", warnings);
  RunRequest request;
  request.mesh_label = "m.off";
  request.particles = 2;
  request.max_iterations = 10;
  request.backend.name = "serial";
  request.init = Init::v0;
  request.start_vertex = 1;  // the file's vertex 1 is the surface's vertex 0
  request.sigma = 0.5;
  request.quiet = true;  // no cache directory: computed
  const RunResult result = run_pipeline(mesh, request);
  const RunOutcome& outcome = result.outcome;
  EXPECT_EQ(result.start, (std::vector<VertexId>{0, 0}));
  EXPECT_EQ(result.plan.paper->scheme, Scheme::sequential) << "the serial backend's default";

  const auto directory = std::filesystem::temp_directory_path() / ("mp_outputs_" + std::to_string(::getpid()));
  prepare_output_directory(directory / "nested");
  const nlohmann::json report = run_report(mesh, result, directory / "nested", "made-up digest");
  write_run_outputs(directory / "nested", mesh, result, report);

  const std::string csv = slurp(directory / "nested" / "particles.csv");
  std::istringstream rows(csv);
  std::string header, row;
  std::getline(rows, header);
  EXPECT_EQ(header, "particle,vertex,x,y,z,corner_a,corner_b,corner_c,weight_a,weight_b,weight_c");
  for (std::size_t i = 0; i < outcome.positions.size(); ++i) {
    ASSERT_TRUE(std::getline(rows, row));
    EXPECT_EQ(row.substr(0, row.find(',', row.find(',') + 1)),
              std::to_string(i) + "," + std::to_string(mesh.input_id(outcome.positions[i])));
  }
  std::istringstream points(slurp(directory / "nested" / "particles.particles"));
  double x, y, z;
  std::size_t lines = 0;
  while (points >> x >> y >> z) ++lines;
  EXPECT_EQ(lines, outcome.positions.size());

  const auto written = nlohmann::json::parse(slurp(directory / "nested" / "report.json"));
  for (const char* key : {"mesh", "params", "device", "iterations_run", "stopped", "trace", "avg_iteration_ms",
                          "quality", "seconds", "distances"}) {
    EXPECT_TRUE(written.contains(key)) << key;
  }
  EXPECT_EQ(written["params"]["start_vertex"], 1);
  EXPECT_EQ(written["params"]["sigma"], 0.5);
  EXPECT_EQ(written["params"]["sigma_from"], "--sigma");
  EXPECT_EQ(written["quality"]["energy"], result.quality.energy);
  EXPECT_EQ(written["stopped"], outcome.converged ? "converged" : "max_iterations");
  EXPECT_EQ(written["trace"].size(), outcome.trace.size());
  EXPECT_FALSE(written.contains("avg_kernel_ms"));  // serial: no kernels
  EXPECT_FALSE(written["trace"][0].contains("balls")) << "no balls on the dense table";

  // ParaView files: a PLY vertex element per particle, a VTK value per vertex.
  std::istringstream ply(slurp(directory / "nested" / "particles.ply"));
  std::string line;
  std::getline(ply, line);
  EXPECT_EQ(line, "ply");
  while (std::getline(ply, line) && line.rfind("element vertex", 0) != 0) {}
  EXPECT_EQ(line, "element vertex " + std::to_string(outcome.positions.size()));
  const std::string vtk = slurp(directory / "nested" / "mesh_distance.vtk");
  EXPECT_NE(vtk.find("POINTS " + std::to_string(mesh.vertex_count()) + " double"), std::string::npos);
  EXPECT_NE(vtk.find("POLYGONS " + std::to_string(mesh.triangle_count())), std::string::npos);
  const auto values_at = vtk.find("LOOKUP_TABLE default\n");
  ASSERT_NE(values_at, std::string::npos);
  std::istringstream values(vtk.substr(values_at + 21));
  std::size_t zeros = 0, count = 0;
  for (double value; values >> value; ++count) zeros += value == 0.0;
  EXPECT_EQ(count, mesh.vertex_count());
  EXPECT_GE(zeros, 1u);  // the vertices the particles sit on

  // The same mesh and values as XML PolyData, which our own reader takes back.
  std::vector<std::string> vtp_warnings;
  const SurfaceMesh from_vtp = read_mesh((directory / "nested" / "mesh_distance.vtp").string(), vtp_warnings);
  ASSERT_EQ(from_vtp.vertex_count(), mesh.vertex_count());
  EXPECT_EQ(from_vtp.triangles(), mesh.triangles());
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    EXPECT_EQ(from_vtp.positions()[v].x, mesh.positions()[v].x) << v;
    EXPECT_EQ(from_vtp.positions()[v].z, mesh.positions()[v].z) << v;
  }
  // The legacy file read back: the same mesh, every coordinate exact.
  std::vector<std::string> vtk_warnings;
  const SurfaceMesh from_vtk = read_mesh((directory / "nested" / "mesh_distance.vtk").string(), vtk_warnings);
  EXPECT_EQ(from_vtk.triangles(), mesh.triangles());
  EXPECT_EQ(from_vtk.positions().size(), mesh.vertex_count());
  for (std::size_t v = 0; v < std::min(from_vtk.vertex_count(), mesh.vertex_count()); ++v) {
    EXPECT_EQ(from_vtk.positions()[v].x, mesh.positions()[v].x) << v;
    EXPECT_EQ(from_vtk.positions()[v].y, mesh.positions()[v].y) << v;
    EXPECT_EQ(from_vtk.positions()[v].z, mesh.positions()[v].z) << v;
  }
  const std::vector<float> vtp_values =
      first_float_array(slurp(directory / "nested" / "mesh_distance.vtp"), "<PointData");
  std::istringstream vtk_values(vtk.substr(values_at + 21));
  ASSERT_EQ(vtp_values.size(), mesh.vertex_count());
  for (const float value : vtp_values) {
    double text_value = 0;
    vtk_values >> text_value;
    EXPECT_FLOAT_EQ(value, float(text_value));
  }
  EXPECT_EQ(written["version"], program_version());
  std::filesystem::remove_all(directory);
}

// Every file that holds coordinates gives back the run's own doubles: far
// from the origin nine significant digits would not (a unit sphere at
// x = 1e7 got its particles in steps of 0.1, and `quality` of the file
// measured other particles than the run's).
std::vector<std::array<double, 3>> coordinates(const std::vector<Vec3>& points) {
  std::vector<std::array<double, 3>> out;
  for (const Vec3& p : points) out.push_back({p.x, p.y, p.z});
  return out;
}

TEST(RunOutputs, FilesHoldTheRunsExactCoordinates) {
  std::vector<std::string> warnings;
  const SurfaceMesh near = read_mesh(std::string(TEST_DATA_DIR) + "/unreferenced_vertices.off", warnings);
  std::vector<Vec3> far_positions = near.positions();
  for (Vec3& p : far_positions) p = p + Vec3{1e7 + 1.0 / 3.0, -2e-7 / 3.0, 1.0 / 7.0};
  const SurfaceMesh mesh(far_positions, near.triangles());
  RunRequest request;
  request.mesh_label = "far.off";
  request.particles = 3;
  request.quiet = true;
  const RunResult result = run_pipeline(mesh, request);
  const auto directory = std::filesystem::temp_directory_path() / ("mp_exact_" + std::to_string(::getpid()));
  prepare_output_directory(directory);
  write_run_outputs(directory, mesh, result, run_report(mesh, result, directory, std::nullopt));
  std::vector<Vec3> expected;
  for (const ParticleLocation& location : particle_locations(mesh, result)) expected.push_back(location.at);
  EXPECT_EQ(coordinates(read_particle_points(directory / "particles.particles")), coordinates(expected));

  std::istringstream rows(slurp(directory / "particles.csv"));
  std::string row;
  std::getline(rows, row);
  std::vector<Vec3> from_csv;
  while (std::getline(rows, row)) {
    std::vector<double> cells;
    std::istringstream fields(row);
    for (std::string cell; std::getline(fields, cell, ',');) cells.push_back(std::stod(cell));
    from_csv.push_back({cells.at(2), cells.at(3), cells.at(4)});
  }
  EXPECT_EQ(coordinates(from_csv), coordinates(expected));

  const std::string ply_text = slurp(directory / "particles.ply");
  EXPECT_NE(ply_text.find("property double x\nproperty double y\nproperty double z\n"), std::string::npos);
  std::istringstream ply(ply_text);
  std::vector<Vec3> from_ply;
  for (std::string line; std::getline(ply, line) && line != "end_header";) {}
  for (Vec3 p; ply >> p.x >> p.y >> p.z;) {
    from_ply.push_back(p);
    ply.ignore(64, '\n');
  }
  EXPECT_EQ(coordinates(from_ply), coordinates(expected));

  // The meshes the particles moved on, as the run had them.
  const SurfaceMesh& moved_on = result.particle_mesh(mesh);
  for (const char* name : {"mesh_distance.vtk", "mesh_distance.vtp"}) {
    const SurfaceMesh back = read_mesh(directory / name, warnings);
    EXPECT_EQ(coordinates(back.positions()), coordinates(moved_on.positions())) << name;
  }
  std::filesystem::remove_all(directory);
}

// spread's particles lie between the input's vertices: each CSV row's
// triangle (input ids) and weights give back its point, on the input surface,
// and its vertex is the nearest corner.
TEST(RunOutputs, SpreadRowsPlaceEachParticleOnAnInputTriangle) {
  std::vector<std::string> warnings;
  const SurfaceMesh mesh = read_mesh(std::string(TEST_DATA_DIR) + "/unreferenced_vertices.off", warnings);
  RunRequest request;
  request.mesh_label = "m.off";
  request.particles = 2;
  request.quiet = true;
  const RunResult result = run_pipeline(mesh, request);
  ASSERT_TRUE(result.spread) << "spread is the default";
  const auto directory = std::filesystem::temp_directory_path() / ("mp_spread_" + std::to_string(::getpid()));
  prepare_output_directory(directory);
  write_run_outputs(directory, mesh, result, run_report(mesh, result, directory, std::nullopt));
  std::istringstream rows(slurp(directory / "particles.csv"));
  std::string row;
  std::getline(rows, row);
  std::size_t count = 0;
  while (std::getline(rows, row)) {
    std::vector<double> cells;
    std::istringstream fields(row);
    for (std::string cell; std::getline(fields, cell, ',');) cells.push_back(std::stod(cell));
    ASSERT_EQ(cells.size(), 11u) << row;
    const Vec3 at{cells[2], cells[3], cells[4]};
    Vec3 from_weights{0, 0, 0};
    double nearest = INFINITY;
    std::size_t nearest_id = 0;
    for (int k = 0; k < 3; ++k) {
      const auto corner = mesh.vertex_of_input_id(std::size_t(cells[5 + k]));
      ASSERT_TRUE(corner) << row;
      from_weights = from_weights + cells[8 + k] * mesh.positions()[*corner];
      if (distance(at, mesh.positions()[*corner]) < nearest) {
        nearest = distance(at, mesh.positions()[*corner]);
        nearest_id = std::size_t(cells[5 + k]);
      }
    }
    EXPECT_LE(distance(at, from_weights), 1e-6 * mesh.mean_edge_length()) << row;
    EXPECT_EQ(std::size_t(cells[1]), nearest_id) << row;
    ++count;
  }
  EXPECT_EQ(count, 2u);
  std::filesystem::remove_all(directory);
}

// The files are written and digested side by side: the same bytes, the
// report's digests among them, on one thread and on several.
TEST(RunOutputs, TheSameFilesOnAnyNumberOfThreads) {
  const SurfaceMesh mesh = committed("sphere.off");
  RunRequest request;
  request.mesh_label = "sphere.off";
  request.particles = 64;
  request.quiet = true;
  const RunResult result = run_pipeline(mesh, request);
  const auto directory = std::filesystem::temp_directory_path() / ("mp_threads_" + std::to_string(::getpid()));
  const nlohmann::json report = run_report(mesh, result, directory, std::nullopt);
  for (const unsigned threads : {1u, 3u}) {
    prepare_output_directory(directory / std::to_string(threads));
    write_run_outputs(directory / std::to_string(threads), mesh, result, report, threads);
  }
  for (const std::string& name : kRunOutputFiles) {
    const std::string one = slurp(directory / "1" / name);
    EXPECT_FALSE(one.empty()) << name;
    EXPECT_EQ(slurp(directory / "3" / name), one) << name;
  }
  std::filesystem::remove_all(directory);
}

TEST(RunOutputs, RefusesAnOutputDirectoryUnderAFile) {
  EXPECT_THROW(prepare_output_directory("/dev/null/out"), UserError);
}

// On local distances each iteration of the trace says how many balls it
// solved and how long the particles waited on them.
TEST(RunOutputs, LocalRunsRecordEachIterationsBalls) {
  std::vector<std::string> warnings;
  const SurfaceMesh mesh = read_mesh(std::string(MESHES_DIR) + "/torus.off", warnings);
  RunRequest request;
  request.mesh_label = "torus.off";
  request.particles = 64;
  request.backend.name = "serial-field";
  request.distances.kind = StoreKind::local;
  request.quiet = true;
  const RunResult result = run_pipeline(mesh, request);
  const nlohmann::json report = run_report(mesh, result, "unused", std::nullopt);
  ASSERT_EQ(report["trace"].size(), result.outcome.trace.size());
  std::size_t balls = 0;
  for (const auto& entry : report["trace"]) {
    ASSERT_TRUE(entry.contains("balls") && entry.contains("ball_ms")) << entry.dump();
    balls += entry["balls"].get<std::size_t>();
  }
  EXPECT_GT(balls, 0u) << "the first moves bring new candidates";
  EXPECT_LE(balls, report["distances"]["balls_computed"].get<std::size_t>());
}

}  // namespace
}  // namespace meshparticles::testing
