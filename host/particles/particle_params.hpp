#pragma once
// What a particle run is asked to do: the potential and its sigma, the update
// scheme and how particles start. docs/ALGORITHM.md is the contract.
#include <cstdint>
#include <string>

namespace meshparticles {

enum class Potential { exp, gauss };
// sequential, synchronous and colored are the paper's and its variants, run
// by the backends themselves; monotone is colored with a guarantee, built on
// them in particles/scheme_step.hpp.
enum class Scheme { sequential, synchronous, colored, monotone };
enum class Init { v0, random, farthest };
// What a run optimizes (docs/ALGORITHM.md): `spread`, the default, moves
// each particle to the largest gap between the others (farthest-point
// optimization) on the input refined until there are enough vertices per
// particle; `paper`, the paper's energy, sigma rule and one-ring moves on
// the input's vertices, on any backend.
enum class Method { spread, paper };
// How the field backends store the weight table W = w(d).
enum class WeightFormat { float32, half };

// The potentials' names, sigma rules and kernel switches: particles/potentials.hpp.
Potential parse_potential(const std::string& name);
Scheme parse_scheme(const std::string& name);
Init parse_init(const std::string& name);
Method parse_method_option(const std::string& name);  // "spread" | "paper"
std::string method_option_name(Method method);
std::string potential_name(Potential potential);
std::string scheme_name(Scheme scheme);
std::string init_name(Init init);
WeightFormat parse_weight_format(const std::string& name);  // "float" | "half"
std::string weight_format_name(WeightFormat format);

// Groups of the colored and monotone schemes when --colors is absent: the
// smallest K that converged like the sequential loop on sphere/1024
// (docs/ALGORITHM.md).
constexpr unsigned kDefaultColors = 16;

// Whether the scheme splits particles into --colors groups.
inline bool uses_colors(Scheme scheme) { return scheme == Scheme::colored || scheme == Scheme::monotone; }

// The term of the distance in each potential's exponent, w(d) =
// exp(-term(d) / (2 sigma^2)): d for exp, d^2 for gauss. The one place
// the potentials differ in the energy; a switch without default, so that a
// third potential does not compile (-Wswitch) until it says its term.
template <typename Real>
constexpr Real distance_term(Potential potential, Real d) {
  switch (potential) {
    case Potential::exp: return d;
    case Potential::gauss: return d * d;
  }
  return d;
}

// The energy's parameters, shared by every backend.
struct EnergyParams {
  Potential potential = Potential::exp;
  double sigma = 0;
  // The factor both potentials multiply by: 1 / (2 sigma^2).
  double inv_two_sigma_sq() const { return 1.0 / (2.0 * sigma * sigma); }
};

// Expected spacing of n particles in a hexagonal packing of area A:
// d_hex = sqrt(2A / (sqrt(3) n)).
double hexagonal_spacing(double area, std::size_t particle_count);

// The default sigma for n particles on area A, chosen by measurement
// (docs/ALGORITHM.md): exp: 2 sigma^2 = d_hex / 2; gauss: sigma = d_hex / 2.
double default_sigma(Potential potential, double area, std::size_t particle_count);

}  // namespace meshparticles
