#pragma once
// The paper's Tables 1 and 2 (Peterson, Datar, Hall, Whitaker): average
// seconds per iteration over 1000 iterations, here in milliseconds. CPU is
// their serial loop, GPU1 the naive and GPU2 the tiled kernel on a GTX 260.
// The atrium at 512 particles has no figures ("possible data processing
// error from the meshing tool").
#include <optional>
#include <string>
#include <vector>

namespace meshparticles {

struct PaperFigures {
  std::string mesh;  // our committed mesh of the same kind
  std::size_t particles;
  std::optional<double> cpu_ms, naive_ms, tiled_ms;
};

inline const std::vector<PaperFigures>& paper_figures() {
  static const std::vector<PaperFigures> figures = {
      {"sphere", 128, 17.7, 0.20, 0.20},
      {"sphere", 256, 76.8008, 0.72, 0.46},
      {"sphere", 512, 313.606, 2.22, 1.10},
      {"sphere", 1024, 1356.15, 7.68, 3.97},
      {"torus", 128, 15.3, 0.19, 0.17},
      {"torus", 256, 64.4005, 0.73, 0.38},
      {"torus", 512, 287.706, 2.24, 0.97},
      {"atrium", 256, 73.7007, 0.73, 0.47},
      {"atrium", 512, 309.306, std::nullopt, std::nullopt},
      {"atrium", 1024, 1240.28, 7.62, 4.57},
  };
  return figures;
}

inline const PaperFigures* paper_figures_for(const std::string& mesh, std::size_t particles) {
  for (const auto& figures : paper_figures()) {
    if (figures.mesh == mesh && figures.particles == particles) return &figures;
  }
  return nullptr;
}

}  // namespace meshparticles
