#pragma once
// A recipe for one VTK file, legacy (.vtk) or XML (.vtp): its encoding and
// layout, a small mesh split into pieces, extra sections the readers read
// past, and tweaks that get chosen numbers of the file wrong. The
// structured fuzz target (vtk_structured_fuzzer.cpp) decodes one from its
// input and writes the file (vtk_recipe_writers.hpp), so libFuzzer's
// mutations land on counts, offsets, pieces and appended ranges instead of
// on bytes that mostly break the syntax.
//
// Decoded front to back; bytes past the end read as 0, and a tweak takes a
// whole group of four bytes, so a one-byte input is a valid file in the
// encoding that byte names, and a seed need say no more.
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace meshparticles::fuzzing {

enum class Encoding : std::uint8_t {
  legacy_ascii,
  legacy_binary,
  vtp_ascii,
  vtp_inline_base64,    // format="binary"
  vtp_appended_raw,     // format="appended", <AppendedData encoding="raw">
  vtp_appended_base64,  // format="appended", <AppendedData encoding="base64">
};
inline constexpr int kEncodings = 6;

inline bool is_legacy(Encoding encoding) {
  return encoding == Encoding::legacy_ascii || encoding == Encoding::legacy_binary;
}

// The numbers of a file a tweak can change. Each tweak names one, a piece,
// an index (which value of an array, or which array) and how to change it.
enum class Site : std::uint8_t {
  point_count,         // POINTS n; NumberOfPoints
  cell_count,          // POLYGONS n, CELLS n, ...; NumberOfPolys, NumberOfStrips
  cell_list_size,      // the size after a legacy cell count
  cell_type_count,     // CELL_TYPES n
  cell_type,           // one CELL_TYPES value
  cell_size,           // one cell's point count in a legacy (pre-5) cell list
  offset_value,        // one value of an offsets array
  connectivity_value,  // one point index
  component_count,     // NumberOfComponents; a FIELD array's components
  tuple_count,         // a FIELD array's tuples
  string_length,       // a binary string's length prefix
  appended_offset,     // a DataArray's offset into the appended data
  block_header,        // an uncompressed block's byte count
  block_count,         // a compressed block's number of blocks
  block_size,          // ... its block size
  last_block_size,     // ... its last block's size
  compressed_size,     // ... one block's compressed size
  // Byte edits of the written file, at a position out of 65,536 of its size
  // (piece * 256 + index).
  truncate_file,
  flip_byte,       // xor with how (0 counts as 0xff)
  repeat_bytes,    // how bytes from the position, written twice
};
inline constexpr int kSites = int(Site::repeat_bytes) + 1;

struct Tweak {
  Site site;
  std::uint8_t piece;
  std::uint8_t index;
  std::uint8_t how;
};

// Which value a tweak may change: the piece, and the index among `of`
// values (or arrays) there.
struct Where {
  std::size_t piece = 0;
  std::size_t index = 0;
  std::size_t of = 1;
};

struct Mesh {
  std::vector<std::array<double, 3>> points;  // exact in float32 and in text
  std::vector<std::vector<long long>> polys, strips;
};

struct Recipe {
  Encoding encoding = Encoding::legacy_ascii;
  // Layout.
  bool compressed = false;      // .vtp binary: vtkZLibDataCompressor
  bool header_uint64 = false;   // .vtp binary: header_type="UInt64"
  bool big_endian = false;      // .vtp binary: byte_order="BigEndian"
  bool split_base64 = false;    // .vtp base64: header and data as two streams, as VTK writes them
  bool version_5 = false;       // .vtk: version 5.1, OFFSETS and CONNECTIVITY
  bool unstructured = false;    // .vtk: DATASET UNSTRUCTURED_GRID
  bool points_double = false;   // Float64 / double points, else Float32 / float
  std::uint8_t index_type = 0;  // 0..3: Int32, Int64, UInt32, UInt64 (.vtk 5.1: int, vtktypeint64, ...)
  std::size_t pieces = 1;       // .vtp only
  std::size_t block_size = 32768;
  // Sections read past.
  bool verts_and_lines = false;
  bool field_data = false;      // .vtk: FIELD with numbers and strings; .vtp: PointData and CellData
  bool metadata = false;        // .vtk: METADATA blocks after arrays
  bool attributes_after = false;  // .vtk: POINT_DATA after the geometry
  std::uint8_t string_width = 0;  // .vtk binary strings: 0 as VTK writes the length, else 2, 4 or 8 bytes
  Mesh mesh;
  std::vector<Tweak> tweaks;

  // A file without tweaks is valid, and must read as expected_soup says.
  bool valid() const { return tweaks.empty(); }

  // `actual`, as the tweaks for that place change it. `related`: another
  // number of the file it could be mistaken for (the point count for an
  // index, the previous array's offset for an offset, ...).
  long long tweaked(Site site, Where where, long long actual, long long related = 0) const;
};

Recipe decode_recipe(std::span<const std::uint8_t> bytes);

}  // namespace meshparticles::fuzzing
