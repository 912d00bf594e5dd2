#pragma once
// "1 vertex", "2 vertices": counts in messages read as English.
#include <cstddef>
#include <string>

namespace meshparticles {

inline std::string plural(std::size_t count, const std::string& one, const std::string& many = "") {
  return std::to_string(count) + " " + (count == 1 ? one : many.empty() ? one + "s" : many);
}

}  // namespace meshparticles
