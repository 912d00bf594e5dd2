#include "particles/particle_params.hpp"

#include <cmath>

#include "common/text_format.hpp"
#include "common/user_error.hpp"
#include "particles/potentials.hpp"

namespace meshparticles {

Potential parse_potential(const std::string& name) {
  for (const PotentialSpec& spec : potential_table()) {
    if (spec.name == name) return spec.potential;
  }
  throw UserError("unknown potential '" + name + "' (choose " + choice_list(potential_names()) + ")");
}

Scheme parse_scheme(const std::string& name) {
  if (name == "sequential") return Scheme::sequential;
  if (name == "synchronous") return Scheme::synchronous;
  if (name == "colored") return Scheme::colored;
  if (name == "monotone") return Scheme::monotone;
  throw UserError("unknown scheme '" + name + "' (choose sequential, synchronous, colored or monotone)");
}

Init parse_init(const std::string& name) {
  if (name == "v0") return Init::v0;
  if (name == "random") return Init::random;
  if (name == "farthest") return Init::farthest;
  throw UserError("unknown start '" + name + "' (choose v0, random or farthest)");
}

Method parse_method_option(const std::string& name) {
  if (name == "spread") return Method::spread;
  if (name == "paper") return Method::paper;
  throw UserError("unknown method '" + name + "' (choose spread or paper)");
}

std::string method_option_name(Method method) {
  switch (method) {
    case Method::spread: return "spread";
    case Method::paper: return "paper";
  }
  return "?";
}

WeightFormat parse_weight_format(const std::string& name) {
  if (name == "float") return WeightFormat::float32;
  if (name == "half") return WeightFormat::half;
  throw UserError("unknown weight format '" + name + "' (choose float or half)");
}

std::string weight_format_name(WeightFormat format) { return format == WeightFormat::float32 ? "float" : "half"; }

std::string potential_name(Potential potential) { return potential_spec(potential).name; }

std::string scheme_name(Scheme scheme) {
  switch (scheme) {
    case Scheme::sequential: return "sequential";
    case Scheme::synchronous: return "synchronous";
    case Scheme::colored: return "colored";
    case Scheme::monotone: return "monotone";
  }
  return "?";
}

std::string init_name(Init init) {
  switch (init) {
    case Init::v0: return "v0";
    case Init::random: return "random";
    case Init::farthest: return "farthest";
  }
  return "?";
}

double hexagonal_spacing(double area, std::size_t particle_count) {
  return std::sqrt(2.0 * area / (std::sqrt(3.0) * double(particle_count)));
}

double default_sigma(Potential potential, double area, std::size_t particle_count) {
  return potential_spec(potential).default_sigma(hexagonal_spacing(area, particle_count));
}

}  // namespace meshparticles
