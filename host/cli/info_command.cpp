#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "common/json_text.hpp"
#include "mesh/io/mesh_reader.hpp"
#include "pipeline/mesh_input.hpp"

namespace meshparticles {

namespace {

struct InfoOptions {
  std::string mesh;
  bool json = false;
  MeshReadOptions read;
};

nlohmann::json mesh_statistics(const SurfaceMesh& mesh) {
  std::size_t min_valence = mesh.vertex_count() ? mesh.valence(0) : 0;
  double valence_sum = 0;
  for (VertexId v = 0; v < mesh.vertex_count(); ++v) {
    min_valence = std::min(min_valence, mesh.valence(v));
    valence_sum += double(mesh.valence(v));
  }
  return {{"vertices", mesh.vertex_count()},
          {"triangles", mesh.triangle_count()},
          {"edges", mesh.edge_count()},
          {"area", mesh.area()},
          {"mean_edge_length", mesh.mean_edge_length()},
          {"valence", {{"min", min_valence}, {"mean", valence_sum / double(mesh.vertex_count())}, {"max", mesh.max_valence()}}},
          {"components", mesh.component_count()},
          {"boundary_vertices", mesh.boundary_vertex_count()}};
}

void run_info(const InfoOptions& options) {
  const SurfaceMesh mesh = load_mesh(options.mesh, false, options.read);
  nlohmann::json stats = mesh_statistics(mesh);
  stats["mesh"] = options.mesh;
  if (options.json) {
    std::cout << json_text(stats, 2) << "\n";
    return;
  }
  const auto& valence = stats["valence"];
  std::printf("mesh              %s\n", options.mesh.c_str());
  std::printf("vertices          %zu\n", mesh.vertex_count());
  std::printf("triangles         %zu\n", mesh.triangle_count());
  std::printf("edges             %zu\n", mesh.edge_count());
  std::printf("area              %.6g\n", mesh.area());
  std::printf("mean edge length  %.6g\n", mesh.mean_edge_length());
  std::printf("valence           min %d, mean %.3f, max %d\n", valence["min"].get<int>(),
              valence["mean"].get<double>(), valence["max"].get<int>());
  std::printf("components        %zu\n", mesh.component_count());
  std::printf("boundary vertices %zu\n", mesh.boundary_vertex_count());
}

}  // namespace

void add_info_command(CLI::App& app) {
  auto options = std::make_shared<InfoOptions>();
  CLI::App* info = app.add_subcommand("info", "Print statistics of a mesh");
  info->add_option("mesh", options->mesh, "Mesh file (" + mesh_extensions() + ")")->required();
  info->add_flag("--json", options->json, "Machine-readable output");
  add_strict_option(*info, options->read);
  info->callback([options] { run_info(*options); });
}

}  // namespace meshparticles
