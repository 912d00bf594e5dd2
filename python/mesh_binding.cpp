// read_mesh and Mesh(vertices, faces): the command line's reader and checks
// (mesh/io/mesh_reader.hpp, mesh/mesh_checks.hpp), so a mesh refused or warned
// about there is refused or warned about here. Warnings go both to
// Mesh.warnings and to Python's warnings module (meshparticles.MeshWarning).
#include <cstdint>
#include <limits>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "argument_values.hpp"
#include "bindings.hpp"
#include "common/memory_limits.hpp"
#include "common/user_error.hpp"
#include "common/utf8_text.hpp"
#include "mesh/io/mesh_reader.hpp"
#include "mesh/mesh_checks.hpp"
#include "mesh_object.hpp"

namespace py = pybind11;

namespace meshparticles::python {

namespace {

PyObject* mesh_warning = nullptr;  // meshparticles.MeshWarning, owned by the module

// What a Mesh's out-of-memory message suggests (common/memory_limits.hpp).
constexpr const char* kMeshMemoryHint = "a smaller mesh needs less";

// Kept in Mesh.warnings and issued through Python's warnings module; a
// file's name that is not UTF-8 is escaped in them (common/utf8_text.hpp).
void publish_warnings(Mesh& mesh) {
  for (auto& warning : mesh.warnings) {
    warning = escaped_utf8(warning);
    // Raises when the caller turned warnings into errors.
    if (PyErr_WarnEx(mesh_warning, warning.c_str(), 1) != 0) throw py::error_already_set();
  }
}

Mesh read_mesh_file(const py::object& path, bool strict) {
  const std::filesystem::path file = path_argument(path, "path");
  Mesh mesh;
  mesh.label = file.string();
  {
    py::gil_scoped_release unlocked;  // a big file takes seconds to read and check
    mesh.surface = naming_memory_failures(mesh.label, "reading the mesh", [&] {
      return std::make_shared<const SurfaceMesh>(read_mesh(file, mesh.warnings, MeshReadOptions{strict}));
    }, kMeshMemoryHint);
  }
  mesh.file = file;
  publish_warnings(mesh);
  return mesh;
}

// `given` as a NumPy array, as np.asarray makes one: lists, tuples and
// arrays of any layout; what is no array of numbers is refused naming `name`.
py::array as_array(const py::object& given, const char* name, const char* expected) {
  try {
    return py::module_::import("numpy").attr("asarray")(given);
  } catch (const py::error_already_set&) {
    throw py::type_error(std::string(name) + ": expected " + expected + ", got " + Py_TYPE(given.ptr())->tp_name);
  }
}

// Unsigned indices past the largest signed one would wrap to negative ids
// in the soup (std::int64_t): refused here with the index as given.
void refuse_huge_indices(const py::array& faces, std::size_t vertex_count) {
  const auto wide = py::array_t<std::uint64_t, py::array::c_style | py::array::forcecast>::ensure(faces);
  const auto f = wide.unchecked<2>();
  for (py::ssize_t t = 0; t < f.shape(0); ++t) {
    for (py::ssize_t k = 0; k < 3; ++k) {
      if (f(t, k) > std::uint64_t(std::numeric_limits<long long>::max())) {
        throw UserError("<arrays>: face " + std::to_string(t) + " refers to vertex " + std::to_string(f(t, k)) +
                        ", out of range (the arrays have " + std::to_string(vertex_count) + " vertices)");
      }
    }
  }
}

// Arrays in, copied into a polygon soup: the checks want it, and the
// surface owns its own arrays.
Mesh mesh_from_arrays(const py::object& vertex_rows, const py::object& face_rows, bool strict) {
  const py::array vertices = as_array(vertex_rows, "vertices", "a (V, 3) array of numbers");
  const py::array faces = as_array(face_rows, "faces", "an (F, 3) array of integers");
  if (vertices.ndim() != 2 || vertices.shape(1) != 3) throw py::value_error("vertices: expected an array of shape (V, 3)");
  if (faces.ndim() != 2 || faces.shape(1) != 3) throw py::value_error("faces: expected an array of shape (F, 3)");
  const char kind = faces.dtype().kind();
  if (kind != 'i' && kind != 'u') throw py::type_error("faces: expected integer vertex indices");
  // Real numbers only: NumPy casts dates, durations, booleans and complex
  // numbers to doubles without a word (datetime64 coordinates made a mesh).
  const char vertex_kind = vertices.dtype().kind();
  if (vertex_kind != 'i' && vertex_kind != 'u' && vertex_kind != 'f') {
    throw py::type_error("vertices: expected a (V, 3) array of numbers, got dtype " +
                         py::str(vertices.dtype()).cast<std::string>());
  }
  const auto points = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(vertices);
  if (!points) {
    PyErr_Clear();
    throw py::type_error("vertices: expected a (V, 3) array of numbers");
  }
  if (kind == 'u') refuse_huge_indices(faces, std::size_t(points.shape(0)));
  const auto indices = py::array_t<long long, py::array::c_style | py::array::forcecast>::ensure(faces);
  Mesh mesh;
  mesh.label = "<arrays>";
  mesh.surface = naming_memory_failures(mesh.label, "building the mesh", [&] {
    PolygonSoup soup;
    const auto p = points.unchecked<2>();
    for (py::ssize_t v = 0; v < p.shape(0); ++v) soup.vertices.push_back({p(v, 0), p(v, 1), p(v, 2)});
    const auto f = indices.unchecked<2>();
    for (py::ssize_t t = 0; t < f.shape(0); ++t) soup.add_triangle(f(t, 0), f(t, 1), f(t, 2));
    return std::make_shared<const SurfaceMesh>(
        build_checked_mesh(soup, mesh.label, mesh.warnings, MeshReadOptions{strict}));
  }, kMeshMemoryHint);
  publish_warnings(mesh);
  return mesh;
}

py::array_t<double> vertex_array(const SurfaceMesh& surface) {
  py::array_t<double> out({py::ssize_t(surface.vertex_count()), py::ssize_t(3)});
  auto o = out.mutable_unchecked<2>();
  for (std::size_t v = 0; v < surface.vertex_count(); ++v) {
    const Vec3& p = surface.positions()[v];
    o(v, 0) = p.x, o(v, 1) = p.y, o(v, 2) = p.z;
  }
  return out;
}

py::array_t<std::int64_t> face_array(const SurfaceMesh& surface) {
  py::array_t<std::int64_t> out({py::ssize_t(surface.triangle_count()), py::ssize_t(3)});
  auto o = out.mutable_unchecked<2>();
  for (std::size_t t = 0; t < surface.triangle_count(); ++t) {
    for (int corner = 0; corner < 3; ++corner) o(t, corner) = surface.triangles()[t][corner];
  }
  return out;
}

py::array_t<std::int64_t> input_id_array(const SurfaceMesh& surface) {
  py::array_t<std::int64_t> out(std::vector<py::ssize_t>{py::ssize_t(surface.vertex_count())});
  auto o = out.mutable_unchecked<1>();
  for (std::size_t v = 0; v < surface.vertex_count(); ++v) o(v) = surface.input_id(VertexId(v));
  return out;
}

}  // namespace

void bind_mesh(py::module_& module) {
  mesh_warning = PyErr_NewExceptionWithDoc("meshparticles._core.MeshWarning",
                                           "A tolerated oddity of a mesh (the command line's warning lines)",
                                           PyExc_UserWarning, nullptr);
  module.add_object("MeshWarning", py::handle(mesh_warning));
  py::class_<Mesh>(module, "Mesh")
      .def(py::init(&mesh_from_arrays), py::arg("vertices"), py::arg("faces"), py::kw_only(),
           py::arg("strict") = false)
      .def_property_readonly("vertices", [](const Mesh& mesh) { return vertex_array(*mesh.surface); })
      .def_property_readonly("faces", [](const Mesh& mesh) { return face_array(*mesh.surface); })
      .def_property_readonly("input_ids", [](const Mesh& mesh) { return input_id_array(*mesh.surface); })
      .def_property_readonly("input_vertex_count", [](const Mesh& mesh) { return mesh.surface->input_vertex_count(); })
      .def_property_readonly("area", [](const Mesh& mesh) { return mesh.surface->area(); })
      .def_property_readonly("mean_edge_length", [](const Mesh& mesh) { return mesh.surface->mean_edge_length(); })
      // The path as os.fsdecode gives it back (a name that is not UTF-8 in
      // surrogate escapes, so that it opens the same file), or "<arrays>".
      .def_property_readonly("label", [](const Mesh& mesh) { return path_text(mesh.label); })
      .def_readonly("warnings", &Mesh::warnings)
      .def("__repr__", [](const Mesh& mesh) {
        return "<meshparticles.Mesh " + escaped_utf8(mesh.label) + ": " + std::to_string(mesh.surface->vertex_count()) +
               " vertices, " + std::to_string(mesh.surface->triangle_count()) + " triangles>";
      });
  module.def("read_mesh", &read_mesh_file, py::arg("path"), py::kw_only(), py::arg("strict") = false);
}

}  // namespace meshparticles::python
