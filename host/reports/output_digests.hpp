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
#include <optional>
#include <string>

namespace meshparticles {

// The text of report.json for `report`, with "outputs" recorded from the
// run's other files in `directory` and "report_sha256" of the result.
// Throws UserError when one of those files cannot be read. The files are
// digested side by side on at most `threads` threads.
std::string digested_report_text(nlohmann::json report, const std::filesystem::path& directory,
                                 unsigned threads = 1);

// The content of report.json at `file` when its text is exactly what
// digested_report_text writes for that content and its "report_sha256"
// holds; else nothing (unreadable, not JSON, edited, or from a version
// before the digests).
std::optional<nlohmann::json> intact_report(const std::filesystem::path& file);

// Whether `report`'s "outputs" names exactly the run's other files and each
// one in `directory` has the size and SHA-256 recorded (sizes first: a
// changed length costs no digest).
bool outputs_as_recorded(const std::filesystem::path& directory, const nlohmann::json& report);

}  // namespace meshparticles
