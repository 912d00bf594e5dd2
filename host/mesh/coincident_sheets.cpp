#include "mesh/coincident_sheets.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <numeric>
#include <tuple>
#include <utility>
#include <vector>

#include "mesh/plural.hpp"

namespace meshparticles {

CoincidentSheets coincident_sheets(const SurfaceMesh& mesh) {
  const std::vector<Vec3>& positions = mesh.positions();
  // Each vertex named by the first vertex at its place.
  std::vector<VertexId> by_place(positions.size());
  std::iota(by_place.begin(), by_place.end(), VertexId(0));
  const auto place = [&](VertexId v) { return std::tie(positions[v].x, positions[v].y, positions[v].z); };
  std::sort(by_place.begin(), by_place.end(), [&](VertexId a, VertexId b) {
    return place(a) < place(b) || (place(a) == place(b) && a < b);
  });
  std::vector<VertexId> place_of(positions.size());
  bool shared = false;
  for (std::size_t k = 0; k < by_place.size(); ++k) {
    const bool same = k > 0 && place(by_place[k]) == place(by_place[k - 1]);
    place_of[by_place[k]] = same ? place_of[by_place[k - 1]] : by_place[k];
    shared = shared || same;
  }
  CoincidentSheets sheets;
  if (!shared) return sheets;  // no two vertices at one place: no two triangles either
  // Each triangle as its three places, sorted; equal ones lie on each other.
  std::vector<std::pair<std::array<VertexId, 3>, std::size_t>> triangles;
  triangles.reserve(mesh.triangle_count());
  for (std::size_t f = 0; f < mesh.triangle_count(); ++f) {
    const Triangle& t = mesh.triangles()[f];
    std::array<VertexId, 3> key{place_of[t[0]], place_of[t[1]], place_of[t[2]]};
    std::sort(key.begin(), key.end());
    if (key[0] == key[1] || key[1] == key[2]) continue;  // not a triangle at its places
    triangles.emplace_back(key, f);
  }
  std::sort(triangles.begin(), triangles.end());
  for (std::size_t begin = 0, end = 0; begin < triangles.size(); begin = end) {
    end = begin + 1;
    while (end < triangles.size() && triangles[end].first == triangles[begin].first) ++end;
    if (end - begin < 2) continue;
    if (sheets.triangles == 0) {
      const Triangle& t = mesh.triangles()[triangles[begin].second];
      sheets.example = (1.0 / 3.0) * (positions[t[0]] + positions[t[1]] + positions[t[2]]);
    }
    sheets.triangles += end - begin;
  }
  return sheets;
}

std::string coincident_sheets_text(const CoincidentSheets& sheets) {
  if (sheets.triangles == 0) return "";
  char at[96];
  std::snprintf(at, sizeof at, "%.6g %.6g %.6g", sheets.example.x, sheets.example.y, sheets.example.z);
  return plural(sheets.triangles, "triangle") + " lie on other triangles (coincident sheets, e.g. at " + at +
         "): a point there is on each sheet, so a particle file cannot say which one its points are on, and "
         "`quality` of it measures them on one";
}

}  // namespace meshparticles
