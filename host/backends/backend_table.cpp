#include "backends/backend_table.hpp"

#include "backends/direct_sum_backend.hpp"
#include "backends/field_backend.hpp"
#include "backends/serial_backend.hpp"
#include "backends/serial_field_backend.hpp"
#include "common/text_format.hpp"
#include "common/user_error.hpp"

namespace meshparticles {

const std::vector<const BackendDescriptor*>& backend_table() {
  static const std::vector<const BackendDescriptor*> table = {
      &serial_backend(),
      &serial_field_backend(),
      &naive_backend(),
      &tiled_backend(),
      &field_backend(),
  };
  return table;
}

const BackendDescriptor& find_backend(const std::string& name) {
  for (const BackendDescriptor* backend : backend_table()) {
    if (backend->name == name) return *backend;
  }
  throw UserError("unknown backend '" + name + "' (choose " + choice_list(backend_names()) + ")");
}

std::vector<std::string> backend_names() {
  std::vector<std::string> names;
  for (const BackendDescriptor* backend : backend_table()) names.push_back(backend->name);
  return names;
}

std::vector<std::string> device_backend_names() {
  std::vector<std::string> names;
  for (const BackendDescriptor* backend : backend_table()) {
    if (backend->on_device()) names.push_back(backend->name);
  }
  return names;
}

}  // namespace meshparticles
