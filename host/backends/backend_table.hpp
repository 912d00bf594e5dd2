#pragma once
// Every backend the program has, in the order help texts and tables list
// them: the one place they are listed. Adding a backend is its own files
// (with its descriptor) plus one line in backend_table.cpp.
#include <string>
#include <vector>

#include "backends/backend_descriptor.hpp"

namespace meshparticles {

const std::vector<const BackendDescriptor*>& backend_table();

// Throws UserError naming the choices for a name no backend has.
const BackendDescriptor& find_backend(const std::string& name);

std::vector<std::string> backend_names();         // every backend
std::vector<std::string> device_backend_names();  // those with an update kernel (sweep --kernel)

}  // namespace meshparticles
