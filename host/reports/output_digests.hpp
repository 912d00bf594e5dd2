#pragma once
// report.json's proof of a run's files, so that a resumed batch keeps an
// output only when every byte of it is as the run wrote it:
//   "outputs"        each other file of the run (particles.particles,
//                    particles.csv, particles.ply, mesh_distance.vtk,
//                    mesh_distance.vtp): {"bytes": size, "sha256": digest},
//                    taken from the files as written, before report.json;
//   "report_sha256"  the SHA-256 of report.json's own text without this
//                    entry: what a file cannot hold of itself.
// report.json's text is always its content as `dump(2)` prints it and a
// newline, so a file whose text is not that (an edit of its white space) was
// not written by a run either.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

namespace meshparticles {

// The text of report.json for `report`, with "outputs" recorded from the
// run's other files in `directory` and "report_sha256" of the result.
// Throws UserError when one of those files cannot be read.
std::string digested_report_text(nlohmann::json report, const std::filesystem::path& directory);

}  // namespace meshparticles
