#include "geodesics/distance_cache.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>

#include "common/atomic_file.hpp"
#include "common/temporary_names.hpp"
#include "common/user_error.hpp"
#include "geodesics/memory_guard.hpp"

namespace meshparticles {

namespace {

constexpr std::array<char, 8> kMagic = {'M', 'P', 'G', 'E', 'O', 'D', 'S', 'T'};
// Bump when the file layout or the solvers' results change (2: fim takes
// its vertices nearest first, 0.18.0).
constexpr std::uint32_t kFormatVersion = 2;

struct CacheHeader {
  std::array<char, 8> magic = kMagic;
  std::uint32_t format_version = kFormatVersion;
  std::uint32_t vertex_count = 0;
  std::uint32_t method = 0;
  std::uint32_t reserved = 0;
  std::uint64_t mesh_hash = 0;
  std::uint64_t values_checksum = 0;
};
static_assert(sizeof(CacheHeader) == 40, "the header is written as raw bytes");

// 64-bit multiply-xorshift over 8-byte words: fast enough to check 400 MB in
// a fraction of a second, and any flipped bit changes it.
std::uint64_t checksum(const void* data, std::size_t bytes) {
  std::uint64_t hash = 0x9E3779B97F4A7C15ull ^ bytes;
  const auto* bytes_in = static_cast<const unsigned char*>(data);
  std::size_t i = 0;
  for (; i + 8 <= bytes; i += 8) {
    std::uint64_t word;
    std::memcpy(&word, bytes_in + i, 8);
    hash = (hash ^ word) * 0xFF51AFD7ED558CCDull;
    hash ^= hash >> 32;
  }
  for (; i < bytes; ++i) hash = (hash ^ bytes_in[i]) * 0x100000001B3ull;
  return hash;
}

std::string format_mode(mode_t mode) {
  char text[8];
  std::snprintf(text, sizeof text, "%04o", unsigned(mode & 07777));
  return text;
}

// Creates the last component 0700 (the parents as usual): the cache is
// this user's alone.
void create_private_directory(const std::filesystem::path& directory) {
  std::error_code error;
  if (directory.has_parent_path()) std::filesystem::create_directories(directory.parent_path(), error);
  if (::mkdir(directory.c_str(), 0700) != 0 && errno != EEXIST) {
    throw UserError("cannot create cache directory " + directory.string() + ": " + std::strerror(errno));
  }
}

void warn(const GeodesicsRequest& request, const std::string& text) {
  if (!request.quiet) std::cerr << "meshparticles: warning: " << text << "\n";
}

}  // namespace

std::filesystem::path default_cache_directory() {
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return std::filesystem::path(xdg) / "meshparticles";
  if (const char* home = std::getenv("HOME"); home && *home) {
    return std::filesystem::path(home) / ".cache" / "meshparticles";
  }
  // A directory of this user's own in the shared temporary directory;
  // cache_directory_problem() refuses it if someone else made it first.
  std::error_code error;
  const std::filesystem::path temporary = std::filesystem::temp_directory_path(error);
  if (error) {
    const char* tmpdir = std::getenv("TMPDIR");
    throw UserError("no cache directory: neither $XDG_CACHE_HOME nor $HOME is set, and $TMPDIR='" +
                    std::string(tmpdir ? tmpdir : "") + "' is not a directory (give --cache-dir or --no-cache)");
  }
  return temporary / ("meshparticles-cache-" + std::to_string(::geteuid()));
}

std::optional<std::string> cache_directory_problem(const std::filesystem::path& directory) {
  struct stat status {};
  if (::lstat(directory.c_str(), &status) != 0) {
    return "cache directory " + directory.string() + ": " + std::strerror(errno);
  }
  if (!S_ISDIR(status.st_mode)) return "cache directory " + directory.string() + " is not a directory";
  if (status.st_uid != ::geteuid()) {
    return "cache directory " + directory.string() + " belongs to user " + std::to_string(status.st_uid) +
           ", not to you";
  }
  if (status.st_mode & (S_IWGRP | S_IWOTH)) {
    return "cache directory " + directory.string() + " can be written by others (mode " +
           format_mode(status.st_mode) + "): anyone could plant a table there";
  }
  return std::nullopt;
}

std::optional<std::string> cache_file_problem(const std::filesystem::path& file) {
  struct stat status {};
  if (::lstat(file.c_str(), &status) != 0) return std::nullopt;  // not cached yet
  if (!S_ISREG(status.st_mode)) return "not a regular file";
  if (status.st_uid != ::geteuid()) return "owned by user " + std::to_string(status.st_uid) + ", not by you";
  if (status.st_mode & (S_IWGRP | S_IWOTH)) return "writable by others (mode " + format_mode(status.st_mode) + ")";
  return std::nullopt;
}

std::uint64_t mesh_content_hash(const SurfaceMesh& mesh) {
  const auto& positions = mesh.positions();
  const auto& triangles = mesh.triangles();
  return checksum(positions.data(), positions.size() * sizeof(Vec3)) ^
         (checksum(triangles.data(), triangles.size() * sizeof(Triangle)) * 3);
}

std::filesystem::path CacheKey::file_in(const std::filesystem::path& directory) const {
  char name[64];
  std::snprintf(name, sizeof name, "%016llx-%u-%s.dist", (unsigned long long)mesh_hash, vertex_count,
                method_name(method).c_str());
  return directory / name;
}

namespace {

// Reads the header and checks it and the file's size against the key.
std::optional<CacheHeader> matching_header(std::ifstream& in, const std::filesystem::path& file, const CacheKey& key,
                                           std::string& problem) {
  CacheHeader header;
  if (!in.read(reinterpret_cast<char*>(&header), sizeof header) || header.magic != kMagic) {
    problem = "not a distance cache file";
    return std::nullopt;
  }
  if (header.format_version != kFormatVersion || header.vertex_count != key.vertex_count ||
      header.method != std::uint32_t(key.method) || header.mesh_hash != key.mesh_hash) {
    problem = "written for another mesh, solver or format version";
    return std::nullopt;
  }
  const std::uint64_t expected_bytes = sizeof header + std::uint64_t(key.vertex_count) * key.vertex_count * sizeof(float);
  std::error_code error;
  if (std::filesystem::file_size(file, error) != expected_bytes) {
    problem = "truncated or overlong";
    return std::nullopt;
  }
  return header;
}

}  // namespace

std::optional<DistanceTable> load_cached_table(const std::filesystem::path& file, const CacheKey& key,
                                               std::string& problem) {
  problem.clear();
  std::ifstream in(file, std::ios::binary);
  if (!in) return std::nullopt;  // not cached yet
  const auto header = matching_header(in, file, key, problem);
  if (!header) return std::nullopt;
  check_table_fits(key.vertex_count, sizeof(float), usable_host_memory_bytes(), "distance table", usable_host_memory_name());
  DistanceTable table(key.vertex_count);
  if (!in.read(reinterpret_cast<char*>(table.values().data()), std::streamsize(table.byte_size()))) {
    problem = "unreadable";
    return std::nullopt;
  }
  if (checksum(table.values().data(), table.byte_size()) != header->values_checksum) {
    problem = "corrupt (checksum mismatch)";
    return std::nullopt;
  }
  return table;
}

void store_cached_table(const std::filesystem::path& file, const CacheKey& key, const DistanceTable& table) {
  CacheHeader header;
  header.vertex_count = key.vertex_count;
  header.method = std::uint32_t(key.method);
  header.mesh_hash = key.mesh_hash;
  header.values_checksum = checksum(table.values().data(), table.byte_size());
  write_file_atomically(
      file,
      [&](std::ostream& out) {
        out.write(reinterpret_cast<const char*>(&header), sizeof header);
        out.write(reinterpret_cast<const char*>(table.values().data()), std::streamsize(table.byte_size()));
      },
      true);
}

DistanceTable load_or_compute_distances(const SurfaceMesh& mesh, const GeodesicsRequest& request,
                                        TableSource& source) {
  source = {};
  const auto compute = [&] { return compute_all_pairs(mesh, request.method, request.threads, request.quiet); };
  if (!request.cache_directory) return compute();
  const std::filesystem::path& directory = *request.cache_directory;
  try {
    create_private_directory(directory);
  } catch (const UserError& failure) {
    warn(request, std::string(failure.what()) + "; not cached");
    return compute();
  }
  if (const auto problem = cache_directory_problem(directory)) {
    warn(request, *problem + "; not used");
    return compute();
  }
  remove_stale_temporaries(directory);

  const CacheKey key{mesh_content_hash(mesh), std::uint32_t(mesh.vertex_count()), request.method};
  source.cache_file = key.file_in(directory);
  std::string problem;
  if (const auto untrusted = cache_file_problem(source.cache_file)) {
    problem = *untrusted;
  } else if (auto cached = load_cached_table(source.cache_file, key, problem)) {
    source.from_cache = true;
    return std::move(*cached);
  }
  if (!problem.empty()) warn(request, "cache file " + source.cache_file.string() + " is " + problem + "; recomputing");
  DistanceTable table = compute();
  try {
    store_cached_table(source.cache_file, key, table);
  } catch (const UserError& failure) {
    warn(request, std::string("not cached: ") + failure.what());
    source.cache_file.clear();
  }
  return table;
}

}  // namespace meshparticles
