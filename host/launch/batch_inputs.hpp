#pragma once
// The meshes of a batch or a correspond from its INPUTS, in order: a mesh file stands for
// itself; a folder for its mesh files (.off, .obj, .ply, .stl, .vtk in any case;
// not its subfolders, where earlier outputs may lie), by name; a .txt file
// for the meshes it lists, one path a line, relative to the list's folder,
// blank lines and lines starting with # skipped. A file given twice (by
// any route) is run once, where it first appears.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace meshparticles {

struct MeshInput {
  std::filesystem::path path;       // as given or joined: names the mesh in messages, reports and the summary
  std::filesystem::path resolved;   // absolute, links resolved: duplicates and output names go by it
  std::uintmax_t bytes = 0;         // the file's size (0 when missing): a free measure of the work
};

// Throws UserError for a folder or a list that cannot be read, a folder
// with no mesh, and a list entry that is not a mesh file. A mesh file that
// is missing or broken is not an error here: its run refuses it, and the
// batch goes on with the others. `notes` gets one line per dropped duplicate
// and per entry of a folder, named as a mesh, that cannot be reached (a
// symlink loop, a link to nothing), skipped.
std::vector<MeshInput> expand_batch_inputs(const std::vector<std::string>& inputs, std::vector<std::string>& notes);

}  // namespace meshparticles
