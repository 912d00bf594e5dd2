// The readers, format by format: the dialects real files are written in, and
// each class of broken file with its one-line message. Small cases are
// written inline and read from memory, as the fuzz harness reads them.
#include "mesh/io/mesh_reader.hpp"

#include <gtest/gtest.h>
#include <zlib.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <algorithm>
#include <array>

#include "common/user_error.hpp"
#include "mesh/io/mesh_file.hpp"
#include "test_files.hpp"

namespace meshparticles {
namespace {


SurfaceMesh read_text(const std::string& text, const MeshFormat& format, std::vector<std::string>& warnings) {
  return build_checked_mesh(read_polygon_soup(std::span<const char>(text.data(), text.size()), format, "text"), "text",
                            warnings);
}

SurfaceMesh read_text(const std::string& text, const MeshFormat& format) {
  std::vector<std::string> warnings;
  SurfaceMesh mesh = read_text(text, format, warnings);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  return mesh;
}

// The message a refused text gives, or "accepted".
std::string refusal(const std::string& text, const MeshFormat& format) {
  try {
    read_text(text, format);
    return "accepted";
  } catch (const UserError& error) {
    const std::string message = error.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_EQ(message.rfind("text: ", 0), 0u) << message;
    return message;
  }
}

#define EXPECT_REFUSED(text, format, expected)                                      \
  do {                                                                              \
    const std::string message = refusal(text, format);                              \
    EXPECT_NE(message.find(expected), std::string::npos) << "message: " << message; \
  } while (0)

const std::string kTetrahedronPoints = "1 1 1\n1 -1 -1\n-1 1 -1\n-1 -1 1\n";
const std::string kTetrahedronFaces = "3 0 1 2\n3 0 3 1\n3 0 2 3\n3 1 3 2\n";

void expect_tetrahedron(const SurfaceMesh& mesh, const std::string& name) {
  ASSERT_EQ(mesh.vertex_count(), 4u) << name;
  EXPECT_EQ(mesh.triangle_count(), 4u) << name;
  EXPECT_NEAR(mesh.area(), 8 * std::sqrt(3.0), 1e-5) << name;
  const Vec3 expected[] = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  for (VertexId v = 0; v < 4; ++v) {
    EXPECT_EQ(mesh.positions()[v].x, expected[v].x) << name << " vertex " << v;
    EXPECT_EQ(mesh.positions()[v].y, expected[v].y) << name << " vertex " << v;
    EXPECT_EQ(mesh.positions()[v].z, expected[v].z) << name << " vertex " << v;
  }
}

TEST(MeshReader, ReadsEveryFormatAndEncodingToTheSameTetrahedron) {
  for (const char* name :
       {"tetrahedron.obj", "tetrahedron.ply", "tetrahedron_binary_le.ply", "tetrahedron_binary_be.ply",
        "tetrahedron_extra_properties.ply", "tetrahedron.stl", "tetrahedron_binary.stl", "tetrahedron_crlf.off"}) {
    std::vector<std::string> warnings;
    expect_tetrahedron(read_mesh(testing::test_data_file(name), warnings), name);
    EXPECT_TRUE(warnings.empty()) << name << ": " << warnings.front();
  }
}

TEST(MeshReader, UnreferencedVerticesAreDroppedAndInputIdsKept) {
  std::vector<std::string> warnings;
  const SurfaceMesh mesh = read_mesh(testing::test_data_file("unreferenced_vertices.off"), warnings);
  ASSERT_EQ(mesh.vertex_count(), 4u);
  EXPECT_EQ(mesh.input_id(0), 1u);
  EXPECT_EQ(mesh.input_id(1), 2u);
  EXPECT_EQ(mesh.input_id(2), 4u);
  EXPECT_EQ(mesh.input_id(3), 5u);
  EXPECT_DOUBLE_EQ(mesh.positions()[0].x, 1.0);
  ASSERT_EQ(warnings.size(), 1u);
}

void expect_unit_cube(const SurfaceMesh& mesh, const std::string& name) {
  EXPECT_EQ(mesh.vertex_count(), 8u) << name;
  EXPECT_EQ(mesh.triangle_count(), 12u) << name;
  EXPECT_NEAR(mesh.area(), 6.0, 1e-12) << name;
  EXPECT_EQ(mesh.boundary_vertex_count(), 0u) << name;
  EXPECT_EQ(long(mesh.vertex_count()) - long(mesh.edge_count()) + long(mesh.triangle_count()), 2) << name;
}

TEST(MeshReader, QuadsAreTriangulated) {
  std::vector<std::string> warnings;
  expect_unit_cube(read_mesh(testing::test_data_file("cube_quads.off"), warnings), "cube_quads.off");
  EXPECT_EQ(warnings.size(), 1u);
}

// --- OFF ---

TEST(OffReader, CommentsBlankLinesColoursAndPolygons) {
  std::vector<std::string> warnings;
  expect_unit_cube(read_mesh(testing::test_data_file("off_dialect.off"), warnings), "off_dialect.off");
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("5 polygons with more than 3 vertices triangulated"), std::string::npos);
}

TEST(OffReader, EveryKeywordGeomviewAllowsAndNone) {
  // One triangle of area 1/2; its vertex lines carry what each prefix adds.
  const std::pair<std::string, std::string> cases[] = {
      {"OFF\n", "0 0 0\n1 0 0\n0 1 0\n"},
      {"COFF\n", "0 0 0 1 0 0 1\n1 0 0 1 0 0 1\n0 1 0 1 0 0 1\n"},
      {"NOFF\n", "0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n"},
      {"CNOFF\n", "0 0 0 0 0 1 1 1 1 1\n1 0 0 0 0 1 1 1 1 1\n0 1 0 0 0 1 1 1 1 1\n"},
      {"STOFF\n", "0 0 0 0 0\n1 0 0 1 0\n0 1 0 0 1\n"},
      {"STCNOFF\n", "0 0 0 0 0 1 1 1 1 1 0 0\n1 0 0 0 0 1 1 1 1 1 1 0\n0 1 0 0 0 1 1 1 1 1 0 1\n"},
      {"nOFF\n3\n", "0 0 0\n1 0 0\n0 1 0\n"},
      {"4OFF\n", "0 0 0 2\n2 0 0 2\n0 2 0 2\n"},  // homogeneous: divided by w
      {"4nOFF 3\n", "0 0 0 0.5\n0.5 0 0 0.5\n0 0.5 0 0.5\n"},
      {"", "0 0 0\n1 0 0\n0 1 0\n"},  // the keyword is optional
  };
  for (const auto& [keyword, vertices] : cases) {
    const SurfaceMesh mesh = read_text(keyword + "3 1 0\n" + vertices + "3 0 1 2\n", mesh_format_of("text.off"));
    EXPECT_EQ(mesh.triangle_count(), 1u) << keyword;
    EXPECT_NEAR(mesh.area(), 0.5, 1e-12) << keyword;
  }
  EXPECT_NEAR(read_text("OFF 3 1\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", mesh_format_of("text.off")).area(), 0.5, 1e-12)
      << "counts on the keyword line, no edge count";
  EXPECT_NEAR(read_text("OFF\r3 1 0\r0 0 0\r1 0 0\r0 1 0\r3 0 1 2", mesh_format_of("text.off")).area(), 0.5, 1e-12)
      << "old Mac line ends, no final line break";
  EXPECT_NEAR(read_text("\xEF\xBB\xBFOFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", mesh_format_of("text.off")).area(), 0.5, 1e-12)
      << "a UTF-8 byte order mark";
}

TEST(OffReader, ContentAfterTheDeclaredFacesIsIgnoredWithAWarning) {
  std::vector<std::string> warnings;
  const SurfaceMesh mesh = read_mesh(testing::test_data_file("trailing_content.off"), warnings);
  EXPECT_EQ(mesh.triangle_count(), 3u);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("1 line after the 3 faces the header declares (from line 10) ignored"), std::string::npos)
      << warnings[0];
}

TEST(OffReader, RefusesWhatItCannotReadWithTheLine) {
  const MeshFormat& off = mesh_format_of("text.off");
  EXPECT_REFUSED("", off, "text: empty file");
  EXPECT_REFUSED("hello world\n", off, "text: line 1: expected an OFF keyword");
  EXPECT_REFUSED("OFF BINARY\n", off, "binary OFF is not supported");
  EXPECT_REFUSED("nOFF 4\n3 1 0\n", off, "line 1: nOFF dimension '4'");
  EXPECT_REFUSED("OFF\nOFF\n3 1 0\n" + kTetrahedronPoints, off,
                 "line 2: expected 'Nvertices Nfaces [Nedges]', found 'OFF'");
  EXPECT_REFUSED("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n", off,
                 "line 6: face 0 declares 0 vertices, fewer than a face needs");
  EXPECT_REFUSED("OFF\n3 x 0\n", off, "line 2: the face count 'x' is not a count");
  EXPECT_REFUSED("OFF\n-3 1 0\n", off, "line 2: the vertex count '-3' is not a count");
  EXPECT_REFUSED("OFF\n3 1 0\n0 0 0\n1 0 zero\n0 1 0\n3 0 1 2\n", off,
                 "line 4: vertex 1: expected a coordinate, found 'zero'");
  EXPECT_REFUSED("OFF\n3 1 0\n0 0 0\n1 0\n0 1 0\n3 0 1 2\n", off,
                 "line 4: vertex 1: expected a coordinate, found the end of the line");
  // The fuzz cases of issue 13: a negative face size, more vertices than declared.
  EXPECT_REFUSED("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n-3 0 2 3\n", off,
                 "line 6: face 0: expected its number of vertices, found '-3'");
  EXPECT_REFUSED("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n0.5 1 0\n3 0 1 2\n", off,
                 "line 6: face 0: expected its number of vertices, found '0.5'");
  EXPECT_REFUSED("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4 0 1 2\n", off,
                 "line 6: face 0 lists 3 of the 4 vertices it declares");
  EXPECT_REFUSED("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 two\n", off,
                 "line 6: face 0: expected a vertex index, found 'two'");
  // Counts the rest of the file cannot hold are refused before anything is allocated.
  EXPECT_REFUSED("OFF\n2147483647 1 0\n0 0 0\n", off,
                 "header declares 2147483647 vertices and 1 face, more than the 6 bytes after it can hold");
  EXPECT_REFUSED("OFF\n3 18446744073709551615 0\n", off, "the face count '18446744073709551615' is not a count");
  EXPECT_REFUSED("OFF\n4 4 6\n" + kTetrahedronPoints + "3 0 1 2\n3 0 3 1\n3 0 2 3\n", off,
                 "file ends after 3 of the 4 faces");
}

// --- PLY ---

TEST(PlyReader, TriangleStripsWithRestartsAndDegenerateJoins) {
  std::vector<std::string> warnings;
  const SurfaceMesh mesh = read_mesh(testing::test_data_file("octahedron_tristrips.ply"), warnings);
  EXPECT_TRUE(warnings.empty()) << warnings.front();  // strip winding alternates: orientation is consistent
  EXPECT_EQ(mesh.vertex_count(), 6u);
  EXPECT_EQ(mesh.triangle_count(), 8u);
  EXPECT_NEAR(mesh.area(), 4 * std::sqrt(3.0), 1e-6);
  EXPECT_EQ(mesh.boundary_vertex_count(), 0u);
}

TEST(PlyReader, AsciiVariants) {
  const std::string header = "ply\r\nformat ascii 1.0\r\ncomment CRLF line ends\r\nobj_info made by hand\r\n";
  const std::string vertices = "element vertex 4\r\nproperty float32 x\r\nproperty float64 y\r\nproperty int8 z\r\n";
  // vertex_index (singular) as some writers name it; an empty list on an extra element.
  const SurfaceMesh mesh = read_text(header + vertices + "element material 1\r\nproperty list uint8 float names\r\n" +
                                         "element face 4\r\nproperty list uint8 int32 vertex_index\r\nend_header\r\n" +
                                         kTetrahedronPoints + "0\n" + kTetrahedronFaces,
                                     mesh_format_of("text.ply"));
  expect_tetrahedron(mesh, "ascii variants");
}

TEST(PlyReader, RefusesWhatItCannotRead) {
  const MeshFormat& ply = mesh_format_of("text.ply");
  const std::string start =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n";
  const std::string faces = "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  const std::string points = "0 0 0\n1 0 0\n0 1 0\n";
  EXPECT_EQ(refusal(start + faces + points + "3 0 1 2\n", ply), "accepted");
  EXPECT_REFUSED("OFF\n", ply, "text: not a PLY file");
  // Issue 13: a header cut off inside an element line used to spin forever.
  EXPECT_REFUSED(start + "element", ply, "line 7: expected 'element NAME COUNT'");
  EXPECT_REFUSED(start, ply, "the header ends without 'end_header'");
  EXPECT_REFUSED("ply\nelement vertex 0\nend_header\n", ply, "the header has no 'format' line");
  EXPECT_REFUSED("ply\nformat binary_middle_endian 1.0\n", ply, "line 2: unknown format 'binary_middle_endian'");
  EXPECT_REFUSED("ply\nformat ascii 1.0\nproperty float x\n", ply, "line 3: a property before any element");
  EXPECT_REFUSED("ply\nformat ascii 1.0\nelement vertex 1\nproperty float128 x\n", ply,
                 "line 4: expected 'property TYPE NAME'");
  EXPECT_REFUSED("ply\nformat ascii 1.0\nelement face 1\nproperty list float int vertex_indices\n", ply,
                 "line 4: a list's count type must be an integer type, found 'float'");
  EXPECT_REFUSED("ply\nformat ascii 1.0\nelement vertex 1\nelement vertex 1\n", ply,
                 "line 4: a second 'vertex' element");
  EXPECT_REFUSED("ply\nformat ascii 1.0\nvertex 1\n", ply, "line 3: unknown header line 'vertex 1'");
  // Issue 13: counts no file this size can hold, refused before allocating.
  EXPECT_REFUSED(
      "ply\nformat binary_little_endian 1.0\nelement vertex 2147483647\nproperty float x\nproperty float y\n"
      "property float z\nend_header\n" +
          std::string(12, '\0'),
      ply, "header declares 2147483647 'vertex' elements, more than the 12 bytes after it can hold");
  // Fuzz finding: a name of 400 unprintable bytes went into the message as it was.
  EXPECT_REFUSED("ply\nformat ascii 1.0\nelement " + std::string(400, '\xff') + " x\n", ply,
                 "line 3: the count of element '????????????????????????????????????????...', 'x', is not a count");
  EXPECT_REFUSED("ply\nformat ascii 1.0\nelement vertex 18446744073709551615\n", ply,
                 "line 3: the count of element 'vertex', '18446744073709551615', is not a count");
  EXPECT_REFUSED("ply\nformat ascii 1.0\nelement vertex 1\nproperty float y\nproperty float z\nend_header\n0 0\n", ply,
                 "the vertex element has no scalar property 'x'");
  EXPECT_REFUSED("ply\nformat ascii 1.0\nelement face 1\nproperty list uchar int indices\nend_header\n3 0 1 2\n", ply,
                 "the face element has no list property 'vertex_indices'");
  EXPECT_REFUSED(
      "ply\nformat ascii 1.0\nelement face 1\nproperty list uchar float vertex_indices\nend_header\n3 0 1 2\n", ply,
      "the face element's vertex indices are not of an integer type");
  EXPECT_REFUSED(start + faces + points + "3 0 1\n", ply, "file ends inside element 'face' record 0 of 1");
  EXPECT_REFUSED(start + faces + points + "3 0 1 2.5\n", ply,
                 "line 13: element 'face' record 0 has a vertex index that is not a whole number");
  EXPECT_REFUSED(start + faces + points + "-3 0 1 2\n", ply, "line 13: element 'face' record 0 has a list length that is not a count");
  EXPECT_REFUSED(start + faces + "0 0 0\n1 0 zero\n0 1 0\n3 0 1 2\n", ply, "line 11: expected a number, found 'zero'");
}

TEST(PlyReader, TruncatedBinaryAndDataAfterTheElements) {
  std::ifstream input(testing::test_data_file("tetrahedron_binary_le.ply"), std::ios::binary);
  const std::string whole((std::istreambuf_iterator<char>(input)), std::istreambuf_iterator<char>());
  EXPECT_REFUSED(whole.substr(0, whole.size() - 3), mesh_format_of("text.ply"), "text: file ends inside element 'face' record 3 of 4");
  std::vector<std::string> warnings;
  expect_tetrahedron(read_text(whole + "extra", mesh_format_of("text.ply"), warnings), "data after the elements");
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0], "text: data after the elements the header declares ignored");
}

// --- legacy VTK ---

// The committed patch mesh as VTK's own writers (legacy 4.2 and 5.1, ASCII
// and binary, with point normals, cell labels and field data; as triangle
// strips from vtkStripper; XML .vtp in ascii, inline binary and appended raw
// and base64 data, zlib-compressed or not, 32- and 64-bit headers) and
// meshio (UNSTRUCTURED_GRID) wrote it
// (tests/data/vtk/make_vtk_files.py): the same points, to the precision the
// ASCII writers print, and the same triangles, each turning the same way.
TEST(VtkReader, FilesFromVtkAndMeshioReadAsTheSameMeshAsOff) {
  std::vector<std::string> warnings;
  const SurfaceMesh off = read_mesh(std::string(MESHES_DIR) + "/patch.off", warnings);
  const auto triangles_of = [](const SurfaceMesh& mesh) {
    std::set<std::array<VertexId, 3>> triangles;
    for (Triangle corners : mesh.triangles()) {
      std::rotate(corners.begin(), std::min_element(corners.begin(), corners.end()), corners.end());
      triangles.insert(corners);
    }
    return triangles;
  };
  const auto expected = triangles_of(off);
  for (const char* name : {"patch_vtk42_ascii.vtk", "patch_vtk42_binary.vtk", "patch_vtk51_ascii.vtk",
                           "patch_vtk51_binary.vtk", "patch_strips_vtk42_ascii.vtk", "patch_strips_vtk51_binary.vtk",
                           "patch_meshio_ascii.vtk", "patch_meshio_binary.vtk", "patch_ascii.vtp", "patch_binary.vtp",
                           "patch_binary_zlib.vtp", "patch_appended_raw.vtp", "patch_appended_raw_zlib.vtp",
                           "patch_appended_base64_zlib.vtp", "patch_strips_appended_raw.vtp"}) {
    SCOPED_TRACE(name);
    std::vector<std::string> vtk_warnings;
    const SurfaceMesh vtk = read_mesh(testing::test_data_file(std::string("vtk/") + name), vtk_warnings);
    EXPECT_TRUE(vtk_warnings.empty()) << vtk_warnings.front();
    ASSERT_EQ(vtk.vertex_count(), off.vertex_count());
    for (VertexId v = 0; v < off.vertex_count(); ++v) {
      ASSERT_LT(distance(vtk.positions()[v], off.positions()[v]), 1e-6) << "vertex " << v;
    }
    EXPECT_EQ(triangles_of(vtk), expected);
  }
}

// A tetrahedron as VTK 9.7.2 writes it by default, with a FIELD array of
// strings (issue 50; tests/data/vtk/make_vtk_files.py): in binary legacy
// files the strings' lengths take 1, 2 and 4 bytes, and one string is
// empty and one holds a line break.
TEST(VtkReader, ReadsPastBinaryStringArraysVtkWrote) {
  for (const char* name : {"tetrahedron_strings_vtk42_binary.vtk", "tetrahedron_strings_vtk51_binary.vtk"}) {
    SCOPED_TRACE(name);
    std::vector<std::string> warnings;
    const SurfaceMesh mesh = read_mesh(testing::test_data_file(std::string("vtk/") + name), warnings);
    EXPECT_TRUE(warnings.empty()) << warnings.front();
    EXPECT_EQ(mesh.vertex_count(), 4u);
    EXPECT_EQ(mesh.triangle_count(), 4u);
  }
}

// Binary strings as vtkDataWriter writes them: each length big-endian in
// 1, 2, 4 or 8 bytes, as the top two bits of its first byte say.
TEST(VtkReader, ReadsPastBinaryStringsOfEveryLengthWidth) {
  const MeshFormat& vtk = mesh_format_of("text.vtk");
  const auto file = [](long long count, const std::string& strings) {
    // A triangle: three big-endian float points, one polygon of int.
    const std::string points("\0\0\0\0\0\0\0\0\0\0\0\0\x3f\x80\0\0\0\0\0\0\0\0\0\0"
                             "\0\0\0\0\x3f\x80\0\0\0\0\0\0", 36);
    const std::string polygon("\0\0\0\x03\0\0\0\0\0\0\0\x01\0\0\0\x02", 16);
    return "# vtk DataFile Version 4.2\ntitle\nBINARY\nDATASET POLYDATA\nFIELD FieldData 1\nnames 1 " +
           std::to_string(count) + " string\n" + strings + "\nPOINTS 3 float\n" + points + "\nPOLYGONS 1 4\n" +
           polygon + "\n";
  };
  // "abc" with its length in 8 bytes, "hi" in 1, "" in 2, "xyz" in 4.
  const std::string widths = std::string("\0\0\0\0\0\0\0\x03" "abc", 11) + "\xc2" "hi" +
                             std::string("\x80\0", 2) + std::string("\x40\0\0\x03" "xyz", 7);
  EXPECT_EQ(refusal(file(4, widths), vtk), "accepted");
  // A string whose bytes hold a line break and a keyword is still only a string.
  EXPECT_EQ(refusal(file(1, "\xcd" "a\nPOLYGONS 9\n"), vtk), "accepted");
  EXPECT_REFUSED(file(1, std::string("\x40\0\x10\0" "xyz", 7)), vtk,
                 "FIELD string 0 of 4096 bytes runs past the end of the file");
  EXPECT_REFUSED(file(1, "\x3f\xff\xff\xff\xff\xff\xff\xff"), vtk,
                 "FIELD string 0 of 4611686018427387903 bytes runs past the end of the file");
  EXPECT_REFUSED(file(1000000, "\xc0"), vtk, "FIELD array of 1000000 strings, more than the");
}

TEST(VtkReader, RefusesWhatItCannotRead) {
  const MeshFormat& vtk = mesh_format_of("text.vtk");
  const std::string head = "# vtk DataFile Version 3.0\ntitle\nASCII\nDATASET POLYDATA\n";
  const std::string points = "POINTS 3 float\n0 0 0 1 0 0 0 1 0\n";
  EXPECT_EQ(refusal(head + points + "POLYGONS 1 4\n3 0 1 2\n", vtk), "accepted");
  EXPECT_EQ(refusal(head + points + "LINES 1 3\n2 0 1\nPOLYGONS 1 4\n3 0 1 2\nPOINT_DATA 3\nanything", vtk),
            "accepted");
  // A METADATA block without its closing empty line swallowed the sections
  // after it without a word (issue 50, item 1).
  const std::string metadata = "METADATA\nINFORMATION 0\n";
  EXPECT_EQ(refusal(head + points + metadata + "\nPOLYGONS 1 4\n3 0 1 2\n", vtk), "accepted");
  EXPECT_REFUSED(head + points + metadata + "POLYGONS 1 4\n3 0 1 2\n", vtk,
                 "a METADATA block runs into POLYGONS without the empty line that ends it");
  // FIELD arrays of strings, one per line (escaped, so one may be empty),
  // as VTK's legacy reader takes them (issue 50, item 4).
  const std::string strings = "FIELD FieldData 2\nnames 1 2 string\nfirst%20name\n\ncounts 1 1 int\n7\n";
  EXPECT_EQ(refusal(head + points + strings + "POLYGONS 1 4\n3 0 1 2\n", vtk), "accepted");
  EXPECT_REFUSED(head + points + "FIELD FieldData 1\nnames 1 3 string\none\n", vtk,
                 "file ends inside a FIELD array of strings");
  EXPECT_REFUSED("OFF\n", vtk, "line 1: expected '# vtk DataFile Version'");
  EXPECT_REFUSED("# vtk DataFile Version 3.0\ntitle\nTEXT\n", vtk, "line 3: expected ASCII or BINARY");
  EXPECT_REFUSED("# vtk DataFile Version 3.0\ntitle\nASCII\nDATASET STRUCTURED_POINTS\n", vtk,
                 "DATASET 'STRUCTURED_POINTS': only POLYDATA and UNSTRUCTURED_GRID are read");
  EXPECT_REFUSED(head + "POINTS 3 float128\n", vtk, "unknown data type 'float128'");
  EXPECT_REFUSED(head + "POINTS 3 float\n0 0 0 1 0 0 0 one 0\n", vtk, "point 2: expected a number, got 'one'");
  EXPECT_REFUSED(head + points + "POLYGONS 1 4\n4 0 1 2\n", vtk, "POLYGONS: cell 0 claims 4 points, past the list");
  EXPECT_REFUSED(head + points + "POLYGONS 2 4\n3 0 1 2\n", vtk, "POLYGONS: the list ends after 1 cell of 2");
  EXPECT_REFUSED(head + points + "CELLS 1 4\n3 0 1 2\n", vtk, "unexpected 'CELLS' in a POLYDATA dataset");
  EXPECT_REFUSED(head + "POLYGONS 0 0\n", vtk, "the dataset has no POINTS");
  // Counts no file this size can hold, refused before allocating.
  EXPECT_REFUSED("# vtk DataFile Version 3.0\ntitle\nBINARY\nDATASET POLYDATA\nPOINTS 2000000000 double\n" +
                     std::string(24, '\0'),
                 vtk, "POINTS: 6000000000 values, more than the 24 bytes after it can hold");
  EXPECT_REFUSED(head + points + "POLYGONS 1 4000000000\n3 0 1 2\n", vtk, "more than the");
  // Version 5.1's offsets must span the connectivity.
  const std::string head51 = "# vtk DataFile Version 5.1\ntitle\nASCII\nDATASET POLYDATA\n";
  EXPECT_EQ(refusal(head51 + points + "POLYGONS 2 3\nOFFSETS vtktypeint64\n0 3\nCONNECTIVITY vtktypeint64\n0 1 2\n",
                    vtk),
            "accepted");
  EXPECT_REFUSED(head51 + points + "POLYGONS 2 3\nOFFSETS vtktypeint64\n0 4\nCONNECTIVITY vtktypeint64\n0 1 2\n",
                 vtk, "the offsets do not span the connectivity's 3 values");
  // Unstructured grids: surface cells only.
  const std::string grid = "# vtk DataFile Version 3.0\ntitle\nASCII\nDATASET UNSTRUCTURED_GRID\n";
  const std::string tetra = "POINTS 4 float\n0 0 0 1 0 0 0 1 0 0 0 1\nCELLS 1 5\n4 0 1 2 3\nCELL_TYPES 1\n10\n";
  EXPECT_REFUSED(grid + tetra, vtk, "cell 0 has VTK cell type 10, not a surface cell");
  EXPECT_REFUSED(grid + points + "CELLS 1 4\n3 0 1 2\n", vtk, "CELLS without CELL_TYPES");
  EXPECT_EQ(refusal(grid + points + "CELLS 2 6\n3 0 1 2\n1 0\nCELL_TYPES 2\n5\n1\n", vtk), "accepted");
}

// The structured fuzz target's first finding (issue 50): a compressed
// array of one block smaller than the header's block size, as VTK writes
// every array under 32768 bytes by default, was refused ("its header claims
// 32768 bytes where the array's values take 48"). A tetrahedron from VTK
// 9.7.2 (tests/data/vtk/make_vtk_files.py).
TEST(VtpReader, ReadsCompressedArraysOfOneBlockSmallerThanTheBlockSize) {
  std::vector<std::string> warnings;
  const SurfaceMesh mesh = read_mesh(testing::test_data_file("vtk/tetrahedron_zlib_one_small_block.vtp"), warnings);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  EXPECT_EQ(mesh.vertex_count(), 4u);
  EXPECT_EQ(mesh.triangle_count(), 4u);
}

TEST(VtpReader, RefusesWhatItCannotRead) {
  const MeshFormat& vtp = mesh_format_of("text.vtp");
  const auto file = [](const std::string& attributes, const std::string& piece, const std::string& body) {
    return "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\"" +
           attributes + ">\n<PolyData>\n<Piece " + piece + ">\n" + body + "</Piece>\n</PolyData>\n</VTKFile>\n";
  };
  const std::string points =
      "<Points><DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"ascii\">0 0 0 1 0 0 0 1 0"
      "</DataArray></Points>\n";
  const std::string polys =
      "<Polys><DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">0 1 2</DataArray>"
      "<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">3</DataArray></Polys>\n";
  const std::string triangle = "NumberOfPoints=\"3\" NumberOfPolys=\"1\"";
  EXPECT_EQ(refusal(file("", triangle, points + polys), vtp), "accepted");
  // Issue 50, item 1: ASCII values past the counts were dropped without a
  // word (a closed tetrahedron with NumberOfPolys="3" read as 3 triangles).
  const std::string tetrahedron_points =
      "<Points><DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"ascii\">0 0 0 1 0 0 0 1 0 0 0 1"
      "</DataArray></Points>\n";
  const std::string four_polys =
      "<Polys><DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">0 2 1 0 1 3 1 2 3 0 3 2</DataArray>"
      "<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">3 6 9 12</DataArray></Polys>\n";
  EXPECT_EQ(refusal(file("", "NumberOfPoints=\"4\" NumberOfPolys=\"4\"", tetrahedron_points + four_polys), vtp),
            "accepted");
  EXPECT_REFUSED(file("", "NumberOfPoints=\"4\" NumberOfPolys=\"3\"", tetrahedron_points + four_polys), vtp,
                 "<Polys> offsets: more than its 3 values (then '12')");
  EXPECT_REFUSED(file("", triangle, points + polys.substr(0, polys.find("2</DataArray>") + 1) + " x" +
                                        polys.substr(polys.find("2</DataArray>") + 1)),
                 vtp, "<Polys> connectivity: more than its 3 values (then 'x')");
  EXPECT_REFUSED("not xml", vtp, "not well-formed XML");
  // The text "<AppendedData" in a comment is not the element (issue 50, item 4).
  EXPECT_EQ(refusal(file("", triangle, "<!-- <AppendedData encoding=\"raw\"> is below -->\n" + points + polys), vtp),
            "accepted");
  // Issue 50, item 3: the inflation bound holds for the whole file. Forty
  // pieces of 100,000 points, all at offset 0 of one appended zlib block of
  // zeros, each within the bound alone: refused at once, not after 1.6 GB
  // (now at the second piece: it reads the first one's bytes).
  {
    constexpr std::uint32_t kPoints = 100000, kBytes = 3 * 4 * kPoints;
    const std::vector<unsigned char> zeros(kBytes, 0);
    std::vector<unsigned char> packed(compressBound(kBytes));
    uLongf packed_size = packed.size();
    ASSERT_EQ(compress2(packed.data(), &packed_size, zeros.data(), kBytes, 9), Z_OK);
    const std::uint32_t header[4] = {1, kBytes, kBytes, std::uint32_t(packed_size)};
    std::string appended(reinterpret_cast<const char*>(header), sizeof header);
    appended.append(reinterpret_cast<const char*>(packed.data()), packed_size);
    std::string bomb = "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" "
                       "compressor=\"vtkZLibDataCompressor\">\n<PolyData>\n";
    for (int k = 0; k < 40; ++k) {
      bomb += "<Piece NumberOfPoints=\"" + std::to_string(kPoints) + "\" NumberOfPolys=\"0\"><Points><DataArray "
              "type=\"Float32\" NumberOfComponents=\"3\" format=\"appended\" offset=\"0\"/></Points></Piece>\n";
    }
    bomb += "</PolyData>\n<AppendedData encoding=\"raw\">_" + appended + "</AppendedData>\n</VTKFile>\n";
    EXPECT_REFUSED(bomb, vtp, "<Points>: its appended data (bytes 0 to ");
  }
  // Uncompressed, such pieces stayed within the inflation bound (2.4 MB
  // took 1.6 GB): arrays that read the same appended bytes are refused.
  // The sample's two pieces are each a triangle whose three arrays lie in
  // one raw block; the second's read the first's bytes again.
  {
    std::ifstream in(testing::test_data_file("vtk/aliased_appended_raw.vtp"), std::ios::binary);
    const std::string aliased((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_FALSE(aliased.empty());
    EXPECT_REFUSED(aliased, vtp, "text: <Points>: its appended data (bytes 0 to 40) overlaps another array's "
                                 "(bytes 0 to 40): each array has its own");
    const std::string second_piece = "<Piece NumberOfPoints=\"3\"";
    const std::string one_piece = aliased.substr(0, aliased.rfind(second_piece)) +
                                  aliased.substr(aliased.find("</PolyData>"));
    EXPECT_EQ(refusal(one_piece, vtp), "accepted");
  }
  // Expat's text is not wrapped twice (issue 50, item 4).
  EXPECT_REFUSED("<?xml version=\"1.0\"?>\n<VTKFile <>", vtp, "not well-formed XML (invalid token)");
  EXPECT_REFUSED("<?xml version=\"1.0\"?><Mesh/>", vtp, "expected a <VTKFile> element, found 'Mesh'");
  EXPECT_REFUSED(file(" compressor=\"vtkLZ4DataCompressor\"", triangle, points + polys), vtp,
                 "compressor 'vtkLZ4DataCompressor' is not read");
  EXPECT_REFUSED(file("", "NumberOfPoints=\"4\" NumberOfPolys=\"1\"", points + polys), vtp,
                 "<Points>: 12 values, more than its 17 bytes can hold");
  EXPECT_REFUSED(file("", triangle, points), vtp, "<Polys> has no DataArray named 'offsets'");
  // Found by fuzz_vtp: a value from the file went into the message verbatim.
  std::string unprintable = points;
  unprintable.replace(unprintable.find("ascii"), 5, "asc\x7fi");
  EXPECT_REFUSED(file("", triangle, unprintable + polys), vtp, "<Points>: unknown format 'asc?i'");
  EXPECT_REFUSED(file("", triangle, points + polys.substr(0, polys.find("<DataArray type=\"Int32\" Name=\"offsets")) +
                                        "<DataArray type=\"Int32\" Name=\"offsets\" format=\"binary\">AAAAAA==</DataArray>"
                                        "</Polys>"),
                 vtp, "<Polys> offsets: its header claims 0 bytes where the array's values take 4");
  // A compressed block whose header claims a gigabyte from a few bytes:
  // refused before anything that size is allocated. (3 blocks of 2^30
  // bytes, compressed sizes 1, 1, 1, in base64.)
  EXPECT_REFUSED(file(" compressor=\"vtkZLibDataCompressor\"", "NumberOfPoints=\"268435456\"",
                      "<Points><DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"binary\">"
                      "AwAAAAAAAEAAAAAAAQAAAAEAAAABAAAA eJwDAAAAAAE=</DataArray></Points>"),
                 vtp, "NumberOfPoints 268435456 is more than the file can hold");
  EXPECT_REFUSED(file(" compressor=\"vtkZLibDataCompressor\"", "NumberOfPoints=\"1\"",
                      "<Points><DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"binary\">"
                      "AwAAAAAAAEAAAAAAAQAAAAEAAAABAAAA eJwDAAAAAAE=</DataArray></Points>"),
                 vtp, "its header claims 3 full blocks of 1073741824 bytes, more than the array's values take (12)");
  // Found by fuzz_vtp: a UInt64 block count of 2^64 - 1 went through a
  // double and did not convert back (undefined behaviour).
  EXPECT_REFUSED(file(" compressor=\"vtkZLibDataCompressor\" header_type=\"UInt64\"", "NumberOfPoints=\"1\"",
                      "<Points><DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"binary\">"
                      "//////////8AAAEAAAAAAAAAAAAAAAAA</DataArray></Points>"),
                 vtp, "its header claims 18446744073709551615 blocks, past the data");
  // Issue 50: a piece's indices are its own. One past its points, or
  // negative, silently took another piece's point; one near 2^63 overflowed
  // when shifted past the earlier pieces' points (UBSan).
  const std::string two = "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\">\n<PolyData>\n";
  const auto piece = [&](const std::string& cell) {
    return "<Piece " + triangle + ">\n" + points +
           "<Polys><DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">" + cell +
           "</DataArray><DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">3</DataArray></Polys>\n</Piece>\n";
  };
  const std::string end = "</PolyData>\n</VTKFile>\n";
  // Two pieces of one triangle: read, and said to lie on each other.
  std::vector<std::string> warnings;
  EXPECT_EQ(read_text(two + piece("0 1 2") + piece("0 1 2") + end, vtp, warnings).triangle_count(), 2u);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("2 triangles lie on other triangles (coincident sheets"), std::string::npos);
  EXPECT_REFUSED(two + piece("0 1 3") + piece("0 1 2") + end, vtp,
                 "<Polys>: the point index 3 is outside its piece's 3 points");
  EXPECT_REFUSED(two + piece("0 1 2") + piece("-1 0 1") + end, vtp,
                 "<Polys>: the point index -1 is outside its piece's 3 points");
  EXPECT_REFUSED(two + piece("0 1 2") + piece("0 1 9223372036854775807") + end, vtp,
                 "<Polys>: the point index 9223372036854775807 is outside its piece's 3 points");
}

// --- OBJ ---

TEST(ObjReader, TextureAndNormalEntriesNegativeIndicesGroupsAndContinuations) {
  std::vector<std::string> warnings;
  expect_unit_cube(read_mesh(testing::test_data_file("obj_dialect.obj"), warnings), "obj_dialect.obj");
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("polygons with more than 3 vertices triangulated"), std::string::npos);
}

TEST(ObjReader, RefusesWhatItCannotReadWithTheLine) {
  const MeshFormat& obj = mesh_format_of("text.obj");
  const std::string points = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  EXPECT_EQ(refusal(points + "f -3 -2 -1\n", obj), "accepted");
  EXPECT_REFUSED(points + "f -4 -2 -1\n", obj,
                 "line 4: relative index -4 reaches before the first vertex (3 read so far)");
  EXPECT_REFUSED(points + "f -9223372036854775808 1 2\n", obj,
                 "line 4: relative index -9223372036854775808 reaches before");
  EXPECT_REFUSED(points + "f 0 1 2\n", obj, "line 4: expected a vertex index (from 1, or negative), found '0'");
  EXPECT_REFUSED(points + "f 1/2 a/2 3\n", obj, "line 4: expected a vertex index (from 1, or negative), found 'a/2'");
  EXPECT_REFUSED("v 0 0\n", obj, "line 1: expected a coordinate, found the end of the line");
  EXPECT_REFUSED(points + "vv 1 2 3\n", obj, "line 4: unknown statement 'vv'");
  EXPECT_REFUSED(points + "f 1 2 4\n", obj, "face 0 refers to vertex 3, out of range (the file has 3 vertices)");
  EXPECT_REFUSED(points, obj, "text: the mesh has no faces");
}

// --- STL ---

TEST(StlReader, MergesIdenticalCornersInFirstSeenOrder) {
  // Two triangles sharing an edge; the shared corners once as 0 and once as -0.
  const std::string text =
      "solid two\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 1 0 0\n   vertex 0 1 0\n"
      "  endloop\n endfacet\n FACET NORMAL 0 0 1\n  OUTER LOOP\n   VERTEX 1 -0 0\n   VERTEX 1 1 0\n"
      "   VERTEX -0 1.0 0e0\n  ENDLOOP\n ENDFACET\nendsolid two\nsolid second_solid\nendsolid\n";
  const SurfaceMesh mesh = read_text(text, mesh_format_of("text.stl"));
  EXPECT_EQ(mesh.vertex_count(), 4u);
  EXPECT_EQ(mesh.triangles()[1], (Triangle{1, 3, 2}));
  EXPECT_NEAR(mesh.area(), 1.0, 1e-12);
}

TEST(StlReader, RefusesWhatItCannotRead) {
  const MeshFormat& stl = mesh_format_of("text.stl");
  EXPECT_REFUSED("facet normal 0 0 1\n", stl, "text: not an STL file (too short for binary");
  EXPECT_REFUSED("solid x\n facet normal 0 0 1\n outer loop\n vertex 0 0 0\n", stl, "file ends inside a facet");
  EXPECT_REFUSED("solid x\n facet normal 0 0 1\n outer loop\n vertex 0 0 0\n vertex 1 0 0\n endloop\n endfacet\n", stl,
                 "line 6: a facet with 2 vertices");
  EXPECT_REFUSED("solid x\n facet normal 0 0 one\n", stl, "line 2: expected a number, found 'one'");
  EXPECT_REFUSED("solid x\n facet normal 0 0 1\n outer loop\n vertex 0 0 0\n endfacet\n", stl,
                 "line 5: expected 'vertex' or 'endloop', found 'endfacet'");
  EXPECT_REFUSED("solid x\n", stl, "file ends inside a solid");
  std::string binary(84 + 50 + 7, '\0');
  binary[80] = 1;
  EXPECT_REFUSED(binary, stl, "binary STL header declares 1 triangle (134 bytes) but the file has 141 bytes");
}

// --- Files ---

TEST(MeshFile, RefusesWhatIsNotARegularFileWithoutWaiting) {
  const auto dir = std::filesystem::temp_directory_path() / ("meshparticles_reader_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto fifo = dir / "pipe.off";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const auto device = dir / "random.stl";
  std::filesystem::create_symlink("/dev/urandom", device);
  for (const auto& path : {fifo, device}) {
    std::vector<std::string> warnings;
    try {
      read_mesh(path, warnings);
      ADD_FAILURE() << path << " was accepted";
    } catch (const UserError& error) {
      EXPECT_NE(std::string(error.what()).find("not a regular file"), std::string::npos) << error.what();
    }
  }
  std::filesystem::remove_all(dir);
}

TEST(MeshFile, RefusesAFileOverTheSizeLimit) {
  EXPECT_EQ(read_mesh_file(testing::test_data_file("tetrahedron.obj"), "t", 70).size(), 70u);
  try {
    read_mesh_file(testing::test_data_file("tetrahedron.obj"), "t", 69);
    ADD_FAILURE() << "a 70-byte file read under a 69-byte limit";
  } catch (const UserError& error) {
    EXPECT_EQ(std::string(error.what()), "t: 70 bytes, more than the 69 bytes a mesh file may have");
  }
}

TEST(MeshReader, TheExtensionNamesTheFormatInAnyCase) {
  EXPECT_EQ(mesh_extensions(), ".off, .obj, .ply, .stl, .vtk, .vtp");
  EXPECT_EQ(std::string(mesh_format_of("a/Shape.VTP").extension), ".vtp");
  EXPECT_EQ(mesh_format_of("shape.Off").read, mesh_format_of("shape.off").read);
  try {
    mesh_format_of("shape.xyz");
    ADD_FAILURE() << ".xyz was taken for a mesh format";
  } catch (const UserError& error) {
    EXPECT_EQ(std::string(error.what()),
              "shape.xyz: unknown mesh format '.xyz' (use .off, .obj, .ply, .stl, .vtk, .vtp)");
  }
}

TEST(MeshReader, BrokenFilesThrowOneLineNamingTheFile) {
  for (const char* name : {"missing.off", "unknown_format.xyz", "garbage.off", "empty.off", "no_faces.off",
                           "truncated.off", "face_count_mismatch.off", "nan_coordinate.off", "nan_coordinate.ply",
                           "index_out_of_range.off", "index_out_of_range.obj", "repeated_index.off"}) {
    std::vector<std::string> warnings;
    try {
      read_mesh(testing::test_data_file(name), warnings);
      ADD_FAILURE() << name << " was accepted";
    } catch (const UserError& error) {
      const std::string message = error.what();
      EXPECT_NE(message.find(name), std::string::npos) << message;
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
      EXPECT_EQ(error.exit_code(), 2);
    }
  }
}

}  // namespace
}  // namespace meshparticles
