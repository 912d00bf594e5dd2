#include "common/json_text.hpp"

#include "common/utf8_text.hpp"

namespace meshparticles {

nlohmann::json as_written(const nlohmann::json& value) {
  if (value.is_string()) return escaped_utf8(value.get_ref<const std::string&>());
  if (value.is_array()) {
    nlohmann::json out = nlohmann::json::array();
    for (const auto& element : value) out.push_back(as_written(element));
    return out;
  }
  if (value.is_object()) {
    nlohmann::json out = nlohmann::json::object();
    for (const auto& [key, element] : value.items()) out[escaped_utf8(key)] = as_written(element);
    return out;
  }
  return value;
}

std::string json_text(const nlohmann::json& value, int indent) {
  constexpr int kInvalidUtf8 = 316;  // nlohmann::json's type_error for a string that is not UTF-8
  try {
    return value.dump(indent);
  } catch (const nlohmann::json::type_error& error) {
    // The copy only when needed: a report holds long arrays of numbers.
    if (error.id != kInvalidUtf8) throw;
    return as_written(value).dump(indent);
  }
}

}  // namespace meshparticles
