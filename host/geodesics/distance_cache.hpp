#pragma once
// The on-disk cache of distance tables. A file holds a fixed header (magic,
// format version, V, solver, a hash of the mesh content, a checksum of the
// values) and the float32 table. It is reused only when the header matches
// the request and the size and checksum are right; it is written to a
// temporary file and renamed, so an interrupted run never leaves half a file.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "geodesics/distance_table.hpp"

namespace meshparticles {

// $XDG_CACHE_HOME/meshparticles, else ~/.cache/meshparticles.
std::filesystem::path default_cache_directory();

// A hash of positions and triangles: any change to the mesh changes it.
std::uint64_t mesh_content_hash(const SurfaceMesh& mesh);

struct CacheKey {
  std::uint64_t mesh_hash = 0;
  std::uint32_t vertex_count = 0;
  GeodesicMethod method = GeodesicMethod::fast_marching;

  std::filesystem::path file_in(const std::filesystem::path& directory) const;
};

// The cached table, or nothing when there is no usable file; a file that
// exists but is unusable is described in `problem` (truncated, corrupt, ...).
std::optional<DistanceTable> load_cached_table(const std::filesystem::path& file, const CacheKey& key,
                                               std::string& problem);

void store_cached_table(const std::filesystem::path& file, const CacheKey& key, const DistanceTable& table);

struct TableSource {
  bool from_cache = false;
  std::filesystem::path cache_file;  // empty with --no-cache
};

struct GeodesicsRequest {
  GeodesicMethod method = GeodesicMethod::fast_marching;
  std::optional<std::filesystem::path> cache_directory;  // nothing: no cache
  unsigned threads = 0;
  bool quiet = false;
};

// The table from the cache when it holds a valid one, else computed and
// stored. Problems with the cache are reported on stderr and never fatal
// for reading; a cache that cannot be written is a warning too.
DistanceTable load_or_compute_distances(const SurfaceMesh& mesh, const GeodesicsRequest& request,
                                        TableSource& source);

}  // namespace meshparticles
