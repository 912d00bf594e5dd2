#pragma once
// Each subcommand lives in its own file and registers itself on the app;
// main.cpp only wires them together and turns errors into exit codes.
#include <CLI/CLI.hpp>
#include <string>

#include "geodesics/distance_cache.hpp"
#include "pipeline/distances.hpp"
#include "mesh/mesh_checks.hpp"

namespace meshparticles {

// --device P:D|NAME, shared by every command that uses a device.
void add_device_option(CLI::App& command, std::string& device_request);

// --strict, shared by every command that reads a mesh: refuse non-manifold
// edges and vertices and repeated triangles instead of keeping them.
void add_strict_option(CLI::App& command, MeshReadOptions& read);

// Options of every command that needs the distance table: solver threads,
// cache, quiet.
struct DistanceTableOptions {
  std::string cache_dir;
  bool no_cache = false;
  unsigned threads = 0;
  bool quiet = false;
  GeodesicsRequest request(GeodesicMethod method) const;
};
void add_distance_table_options(CLI::App& command, DistanceTableOptions& options);

// --distances dense|local|auto and --cutoff, for the commands that can run
// on local distances (run, quality, compare).
struct DistanceStoreOptions {
  std::string store = "auto";
  std::optional<double> cutoff;
  DistancesRequest request(const GeodesicsRequest& geodesics) const;
};
void add_distance_store_options(CLI::App& command, DistanceStoreOptions& options);

// --geodesic fmm|fim|dijkstra and --potential (particles/potentials), the same wherever a
// command takes them; `default_note` says what an empty `method` means.
void add_geodesic_option(CLI::App& command, std::string& method, const std::string& default_note = "");
void add_potential_option(CLI::App& command, std::string& potential);

void add_info_command(CLI::App& app);
void add_devices_command(CLI::App& app);
void add_generate_command(CLI::App& app);
void add_geodesics_command(CLI::App& app);
void add_run_command(CLI::App& app);
void add_batch_command(CLI::App& app);
void add_sweep_command(CLI::App& app);
void add_bench_command(CLI::App& app);
void add_quality_command(CLI::App& app);
void add_compare_command(CLI::App& app);
void add_model_command(CLI::App& app);
void add_correspond_command(CLI::App& app);

}  // namespace meshparticles
