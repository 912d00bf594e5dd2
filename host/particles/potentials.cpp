#include "particles/potentials.hpp"

#include <cmath>
#include <stdexcept>

namespace meshparticles {

const std::vector<PotentialSpec>& potential_table() {
  static const std::vector<PotentialSpec> table = {
      {Potential::exp, "exp", "exp(-d/(2 sigma^2))", 0,
       [](double d_hex) { return std::sqrt(d_hex / 4.0); }},  // 2 sigma^2 = d_hex / 2
      {Potential::gauss, "gauss", "exp(-d^2/(2 sigma^2))", 1, [](double d_hex) { return d_hex / 2.0; }},
  };
  return table;
}

const PotentialSpec& potential_spec(Potential potential) {
  for (const PotentialSpec& spec : potential_table()) {
    if (spec.potential == potential) return spec;
  }
  throw std::logic_error("a potential without its entry in potential_table()");
}

std::vector<std::string> potential_names() {
  std::vector<std::string> names;
  for (const PotentialSpec& spec : potential_table()) names.push_back(spec.name);
  return names;
}

}  // namespace meshparticles
