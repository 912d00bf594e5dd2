// A recipe as an XML .vtp file, laid out as VTK's vtkXMLPolyDataWriter
// writes one: a <Piece> per piece, each DataArray ascii, inline base64 or
// appended (raw or base64). A binary array is a block: a header (its byte
// count; compressed: the block count, block size, last block's size and
// each block's compressed size) in UInt32 or UInt64, then the data.
#include <zlib.h>

#include <utility>

#include "recipe_values.hpp"
#include "vtk_recipe_writers.hpp"

namespace meshparticles::fuzzing {

namespace {

// A DataArray's identity for tweaks (Where::index, of kArrays).
enum ArrayId : std::size_t {
  kPoints, kPolysConnectivity, kPolysOffsets, kStripsConnectivity, kStripsOffsets,
  kPointData, kVertsConnectivity, kVertsOffsets, kLinesConnectivity, kLinesOffsets, kArrays
};

std::string base64(const std::string& bytes) {
  static constexpr char kDigits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
    std::uint32_t bits = 0;
    for (std::size_t k = 0; k < 3; ++k) bits = bits << 8 | (k < n ? (unsigned char)bytes[i + k] : 0u);
    for (std::size_t k = 0; k < 4; ++k) out += k <= n ? kDigits[bits >> (18 - 6 * k) & 63] : '=';
  }
  return out;
}

// One array's values, as text and as binary bytes.
struct Values {
  std::string text, bytes;
};

class VtpWriter {
 public:
  explicit VtpWriter(const Recipe& recipe) : recipe_(recipe), mesh_(recipe.mesh) {}

  std::string write() {
    std::string out = std::string("<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"") +
                      (recipe_.big_endian ? "BigEndian" : "LittleEndian") + "\" header_type=\"" +
                      (recipe_.header_uint64 ? "UInt64" : "UInt32") + "\"" +
                      (recipe_.compressed ? " compressor=\"vtkZLibDataCompressor\"" : "") + ">\n<PolyData>\n";
    for (std::size_t p = 0; p < recipe_.pieces; ++p) out += piece(p);
    out += "</PolyData>\n";
    if (appended()) {
      out += std::string("<AppendedData encoding=\"") + (raw_appended() ? "raw" : "base64") + "\">\n   _" + appended_ +
             "\n</AppendedData>\n";
    }
    return out + "</VTKFile>\n";
  }

 private:
  bool appended() const {
    return recipe_.encoding == Encoding::vtp_appended_raw || recipe_.encoding == Encoding::vtp_appended_base64;
  }
  bool raw_appended() const { return recipe_.encoding == Encoding::vtp_appended_raw; }

  long long tweaked(Site site, std::size_t piece, std::size_t index, std::size_t of, long long actual,
                    long long related = 0) const {
    return recipe_.tweaked(site, {piece, index, of}, actual, related);
  }
  std::string count(Site site, std::size_t piece, std::size_t index, std::size_t of, long long actual,
                    long long related) const {
    return "\"" + std::to_string(tweaked(site, piece, index, of, actual, related)) + "\"";
  }

  std::string piece(std::size_t p) {
    const long long points = (long long)mesh_.points.size();
    const long long extra = recipe_.verts_and_lines ? 1 : 0;
    std::string out = "<Piece NumberOfPoints=" + count(Site::point_count, p, 0, 1, points, 3 * points) +
                      " NumberOfVerts=\"" + std::to_string(extra) + "\" NumberOfLines=\"" + std::to_string(extra) +
                      "\" NumberOfStrips=" + cell_count(p, 1, mesh_.strips) +
                      " NumberOfPolys=" + cell_count(p, 0, mesh_.polys) + ">\n";
    if (recipe_.field_data) {
      out += "<PointData Scalars=\"height\">" +
             data_array("type=\"Float32\" Name=\"height\"", reals(std::vector<double>(std::size_t(points), 2.0), false),
                        p, kPointData) +
             "</PointData>\n";
    }
    std::vector<double> xyz;
    for (const auto& point : mesh_.points) xyz.insert(xyz.end(), point.begin(), point.end());
    out += "<Points>" +
           data_array(std::string("type=\"") + (recipe_.points_double ? "Float64" : "Float32") +
                          "\" Name=\"Points\" NumberOfComponents=" + count(Site::component_count, p, 0, 1, 3, 1),
                      reals(xyz, recipe_.points_double), p, kPoints) +
           "</Points>\n";
    if (recipe_.verts_and_lines) {
      out += "<Verts>" + cells(p, kVertsConnectivity, {{0}}) + "</Verts>\n";
      out += "<Lines>" + cells(p, kLinesConnectivity, {{0, 1}}) + "</Lines>\n";
    }
    out += "<Strips>" + cells(p, kStripsConnectivity, mesh_.strips) + "</Strips>\n";
    out += "<Polys>" + cells(p, kPolysConnectivity, mesh_.polys) + "</Polys>\n";
    return out + "</Piece>\n";
  }

  std::string cell_count(std::size_t p, std::size_t which, const std::vector<std::vector<long long>>& cells) const {
    std::size_t size = 0;
    for (const auto& cell : cells) size += cell.size();
    return count(Site::cell_count, p, which, 2, (long long)cells.size(), (long long)size);
  }

  // A cell section's two arrays: connectivity, then offsets (each cell's end).
  std::string cells(std::size_t p, ArrayId connectivity_id, const std::vector<std::vector<long long>>& cells) {
    std::vector<long long> connectivity, offsets;
    for (const auto& cell : cells) {
      for (const long long index : cell) {
        connectivity.push_back(tweaked(Site::connectivity_value, p, connectivity.size(), 256, index,
                                       (long long)mesh_.points.size()));
      }
      offsets.push_back(tweaked(Site::offset_value, p, offsets.size(), 256, (long long)connectivity.size(),
                                offsets.empty() ? 0 : offsets.back()));
    }
    static constexpr const char* kTypes[] = {"Int32", "Int64", "UInt32", "UInt64"};
    const std::string type = std::string("type=\"") + kTypes[recipe_.index_type % 4] + "\"";
    return data_array(type + " Name=\"connectivity\"", integers(connectivity), p, connectivity_id) +
           data_array(type + " Name=\"offsets\"", integers(offsets), p, ArrayId(connectivity_id + 1));
  }

  Values reals(const std::vector<double>& values, bool doubles) const {
    Values out;
    for (const double value : values) {
      out.text += real_text(value) + " ";
      append_binary(out.bytes, doubles ? ValueType::float64 : ValueType::float32, value, 0, recipe_.big_endian);
    }
    return out;
  }

  Values integers(const std::vector<long long>& values) const {
    Values out;
    for (const long long value : values) {
      out.text += std::to_string(value) + " ";
      append_binary(out.bytes, index_type_of(recipe_.index_type), 0, value, recipe_.big_endian);
    }
    return out;
  }

  std::string data_array(const std::string& attributes, const Values& values, std::size_t p, ArrayId id) {
    if (recipe_.encoding == Encoding::vtp_ascii) {
      return "<DataArray " + attributes + " format=\"ascii\">" + values.text + "</DataArray>";
    }
    const auto [header, data] = block(values.bytes, p, id);
    if (!appended()) {
      return "<DataArray " + attributes + " format=\"binary\">" + encoded(header, data) + "</DataArray>";
    }
    const long long offset = (long long)appended_.size();
    appended_ += raw_appended() ? header + data : encoded(header, data);
    const long long shown = tweaked(Site::appended_offset, p, id, kArrays, offset, previous_offset_);
    previous_offset_ = offset;
    return "<DataArray " + attributes + " format=\"appended\" offset=\"" + std::to_string(shown) + "\"/>";
  }

  std::string encoded(const std::string& header, const std::string& data) const {
    return recipe_.split_base64 ? base64(header) + base64(data) : base64(header + data);
  }

  void header_value(std::string& out, long long value) const {
    if (recipe_.header_uint64) {
      append_raw(out, std::uint64_t(value), recipe_.big_endian);
    } else {
      append_raw(out, std::uint32_t(value), recipe_.big_endian);
    }
  }

  // A binary array as (header, data), compressed as the recipe says.
  std::pair<std::string, std::string> block(const std::string& raw, std::size_t p, ArrayId id) {
    const auto tweak = [&](Site site, long long actual, long long related) {
      return tweaked(site, p, id, kArrays, actual, related);
    };
    std::string header;
    if (!recipe_.compressed) {
      header_value(header, tweak(Site::block_header, (long long)raw.size(), 0));
      return {header, raw};
    }
    const std::size_t size = recipe_.block_size;
    const std::size_t blocks = (raw.size() + size - 1) / size;
    header_value(header, tweak(Site::block_count, (long long)blocks, (long long)raw.size()));
    header_value(header, tweak(Site::block_size, (long long)size, (long long)raw.size()));
    header_value(header, tweak(Site::last_block_size, (long long)(raw.size() % size), (long long)size));
    std::string data;
    for (std::size_t b = 0; b < blocks; ++b) {
      const std::string piece_of_raw = raw.substr(b * size, size);
      std::string packed(compressBound(uLong(piece_of_raw.size())), '\0');
      uLongf packed_size = uLongf(packed.size());
      compress2(reinterpret_cast<Bytef*>(packed.data()), &packed_size,
                reinterpret_cast<const Bytef*>(piece_of_raw.data()), uLong(piece_of_raw.size()), 1);
      packed.resize(packed_size);
      header_value(header, tweak(Site::compressed_size, (long long)packed_size, (long long)raw.size()));
      data += packed;
    }
    return {header, data};
  }

  const Recipe& recipe_;
  const Mesh& mesh_;
  std::string appended_;
  long long previous_offset_ = 0;
};

}  // namespace

std::string write_vtp(const Recipe& recipe) { return VtpWriter(recipe).write(); }

}  // namespace meshparticles::fuzzing
