#pragma once
// The name of each mesh's output folder in a batch: the file's name without
// its extension, with characters other than letters, digits, '.', '-' and
// '_' (and a leading '.') replaced by '_'. Where two meshes would get the
// same name (two folders each holding a heart.off), each gets the name
// followed by '+' and 8 hex digits of the SHA-256 of its resolved path: a
// plain name never holds '+', so the two kinds cannot meet, and the names
// depend only on the inputs, never on the order of the work.
#include <string>
#include <vector>

#include "launch/batch_inputs.hpp"

namespace meshparticles {

// Names the batch's own files take, never given to a mesh's folder.
inline const std::vector<std::string> kBatchFileNames = {"summary.csv", "summary.json"};

// One name per input, in order. Throws UserError if two resolved paths
// share a name and their digests' first 8 digits (one chance in 4 billion).
std::vector<std::string> output_names(const std::vector<MeshInput>& meshes);

}  // namespace meshparticles
