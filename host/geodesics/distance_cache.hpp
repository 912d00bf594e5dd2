#pragma once
// The on-disk cache of distance tables. A file holds a fixed header (magic,
// format version, V, solver, a hash of the mesh content, a checksum of the
// values) and the float32 table. It is reused only when the header matches
// the request and the size and checksum are right; it is written to a
// temporary file and renamed, so an interrupted run never leaves half a file
// (and the next one removes what it left).
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "geodesics/distance_table.hpp"

namespace meshparticles {

// $XDG_CACHE_HOME/meshparticles, else ~/.cache/meshparticles, else
// meshparticles-cache-UID in the temporary directory. Throws UserError
// (naming $TMPDIR) when there is none.
std::filesystem::path default_cache_directory();

// Why a cache directory must not be used, if it must not: it is not this
// user's, or others can write it (anyone could plant a table with a valid
// checksum there: a checksum detects damage, not who wrote the file).
std::optional<std::string> cache_directory_problem(const std::filesystem::path& directory);
// The same for one file of it: not a regular file, someone else's, or
// writable by others. Nothing when it is fine or does not exist.
std::optional<std::string> cache_file_problem(const std::filesystem::path& file);

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
  std::string device;  // --device: where fim solves local balls
};

// The table from the cache when it holds a valid one, else computed and
// stored. The directory is created 0700; one that is not this user's, or
// that others can write, is not used, and a file in it that is not this
// user's is recomputed and replaced. Every problem with the cache is a
// warning on stderr, never fatal: the cache only saves time.
DistanceTable load_or_compute_distances(const SurfaceMesh& mesh, const GeodesicsRequest& request,
                                        TableSource& source);

}  // namespace meshparticles
