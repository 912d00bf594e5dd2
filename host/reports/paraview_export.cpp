#include "reports/paraview_export.hpp"

#include <openssl/evp.h>

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "common/atomic_file.hpp"
#include "common/exact_number.hpp"

namespace meshparticles {

namespace {

float finite_or_minus_one(float value) { return std::isinf(value) ? -1.0f : value; }

// One DataArray's content as VTK's uncompressed binary format has it: the
// byte count (UInt64), then the values, base64-encoded together.
template <typename T>
void write_base64_block(std::ostream& out, const std::vector<T>& values) {
  static_assert(std::endian::native == std::endian::little, "the file declares byte_order=\"LittleEndian\"");
  std::vector<unsigned char> bytes(sizeof(std::uint64_t) + values.size() * sizeof(T));
  const std::uint64_t count = values.size() * sizeof(T);
  std::memcpy(bytes.data(), &count, sizeof count);
  if (!values.empty()) std::memcpy(bytes.data() + sizeof count, values.data(), count);
  // Whole groups of 3 bytes per call, so the pieces join without padding.
  constexpr std::size_t kChunk = 3 * 16384;
  std::vector<unsigned char> text(4 * kChunk / 3 + 1);
  for (std::size_t at = 0; at < bytes.size(); at += kChunk) {
    const std::size_t length = std::min(kChunk, bytes.size() - at);
    const int written = EVP_EncodeBlock(text.data(), bytes.data() + at, int(length));
    out.write(reinterpret_cast<const char*>(text.data()), written);
  }
}

// Lines of text gathered and written a chunk at a time, every number by
// std::to_chars: the bytes `<<` and printf give, at a fraction of the cost
// (the working mesh's field is the largest file a run writes).
class TextChunks {
 public:
  explicit TextChunks(std::ostream& out) : out_(out) { text_.reserve(kChunk + 256); }
  void point(const Vec3& p) { append_exact_triple(text_, p.x, p.y, p.z); }
  void integer(std::uint64_t value) {
    char digits[24];
    text_.append(digits, std::to_chars(digits, digits + sizeof digits, value).ptr);
  }
  // As printf's "%.<digits>g".
  void general(double value, int digits) {
    char text[40];
    text_.append(text, std::to_chars(text, text + sizeof text, value, std::chars_format::general, digits).ptr);
  }
  void put(char c) { text_ += c; }
  void end_line() {
    text_ += '\n';
    if (text_.size() >= kChunk) flush();
  }
  void flush() {
    out_.write(text_.data(), std::streamsize(text_.size()));
    text_.clear();
  }

 private:
  static constexpr std::size_t kChunk = 1 << 20;
  std::ostream& out_;
  std::string text_;
};

}  // namespace

void write_particles_ply(const std::filesystem::path& file, std::span<const Vec3> points,
                         std::span<const VertexId> input_vertices) {
  write_file_atomically(file, [&](std::ostream& out) {
    out << "ply\nformat ascii 1.0\ncomment meshparticles particles\nelement vertex " << points.size()
        << "\nproperty double x\nproperty double y\nproperty double z\nproperty int particle\nproperty int vertex\n"
           "end_header\n";
    for (std::size_t i = 0; i < points.size(); ++i) {
      const Vec3& p = points[i];
      out << exact_triple(p.x, p.y, p.z) << " " << i << " " << input_vertices[i] << "\n";
    }
  });
}

void write_mesh_field_vtk(const std::filesystem::path& file, const SurfaceMesh& mesh, std::span<const float> values,
                          const std::string& name) {
  write_file_atomically(file, [&](std::ostream& out) {
    out << "# vtk DataFile Version 3.0\nmeshparticles: " << name << "\nASCII\nDATASET POLYDATA\nPOINTS "
        << mesh.vertex_count() << " double\n";
    TextChunks text(out);
    for (const Vec3& p : mesh.positions()) {
      text.point(p);
      text.end_line();
    }
    text.flush();
    out << "POLYGONS " << mesh.triangle_count() << " " << 4 * mesh.triangle_count() << "\n";
    for (const Triangle& t : mesh.triangles()) {
      text.put('3');
      for (const VertexId corner : t) {
        text.put(' ');
        text.integer(corner);
      }
      text.end_line();
    }
    text.flush();
    out << "POINT_DATA " << mesh.vertex_count() << "\nSCALARS " << name << " float 1\nLOOKUP_TABLE default\n";
    for (const float value : values) {
      text.general(double(finite_or_minus_one(value)), 7);
      text.end_line();
    }
    text.flush();
  });
}

void write_mesh_field_vtp(const std::filesystem::path& file, const SurfaceMesh& mesh, std::span<const float> values,
                          const std::string& name) {
  std::vector<double> points;
  std::vector<float> field;
  points.reserve(3 * mesh.vertex_count());
  for (const Vec3& p : mesh.positions()) points.insert(points.end(), {p.x, p.y, p.z});
  for (const float value : values) field.push_back(finite_or_minus_one(value));
  std::vector<std::int64_t> connectivity, offsets;
  connectivity.reserve(3 * mesh.triangle_count());
  for (const Triangle& t : mesh.triangles()) {
    connectivity.insert(connectivity.end(), {std::int64_t(t[0]), std::int64_t(t[1]), std::int64_t(t[2])});
    offsets.push_back(std::int64_t(connectivity.size()));
  }
  write_file_atomically(file, [&](std::ostream& out) {
    out << "<?xml version=\"1.0\"?>\n"
           "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
           "  <PolyData>\n"
           "    <Piece NumberOfPoints=\""
        << mesh.vertex_count() << "\" NumberOfVerts=\"0\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\""
        << mesh.triangle_count() << "\">\n      <PointData Scalars=\"" << name << "\">\n        <DataArray type=\"Float32\" Name=\""
        << name << "\" format=\"binary\">";
    write_base64_block(out, field);
    out << "</DataArray>\n      </PointData>\n      <Points>\n"
           "        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"binary\">";
    write_base64_block(out, points);
    out << "</DataArray>\n      </Points>\n      <Polys>\n"
           "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"binary\">";
    write_base64_block(out, connectivity);
    out << "</DataArray>\n        <DataArray type=\"Int64\" Name=\"offsets\" format=\"binary\">";
    write_base64_block(out, offsets);
    out << "</DataArray>\n      </Polys>\n    </Piece>\n  </PolyData>\n</VTKFile>\n";
  });
}

}  // namespace meshparticles
