#pragma once
// Whether a mesh's earlier output can stand for the run a batch plans, so a
// resumed batch skips it: checked, never assumed. It can when its folder
// holds exactly a run's files, report.json is intact (its text exactly as a
// run writes it, its own SHA-256 holds: reports/output_digests.hpp), was
// written by this version, names the same mesh (path, SHA-256 of the file,
// vertex count), the same parameters (every one in effect, defaults
// resolved; the output path aside) and the same distance store, and every
// other file has the size and SHA-256 report.json recorded when it was
// written. A killed write never leaves a half set to find
// (reports/run_outputs.hpp), so what fails here was edited, damaged, from
// another version or belongs to other inputs, and the mesh is computed
// again.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "pipeline/run_pipeline.hpp"

namespace meshparticles {

// The earlier report.json when the output in `directory` is a complete run
// of `plan` on `mesh` read from a file with `mesh_sha256`; else nothing.
std::optional<nlohmann::json> reusable_report(const std::filesystem::path& directory, const SurfaceMesh& mesh,
                                              const RunPlan& plan, const std::string& mesh_sha256);

}  // namespace meshparticles
