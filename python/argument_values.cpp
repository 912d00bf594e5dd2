#include "argument_values.hpp"

#include "common/user_error.hpp"
#include "options/option_values.hpp"

namespace py = pybind11;

namespace meshparticles::python {

namespace {

std::string type_name(py::handle value) { return Py_TYPE(value.ptr())->tp_name; }

[[noreturn]] void refuse_type(py::handle value, const std::string& name, const std::string& expected) {
  throw py::type_error(name + ": expected " + expected + ", got " + type_name(value));
}

bool is_text(py::handle value) { return PyUnicode_Check(value.ptr()) || PyBytes_Check(value.ptr()); }

}  // namespace

std::uint64_t whole_number(py::handle value, const std::string& name, WholeRange range) {
  if (PyBool_Check(value.ptr()) || !PyIndex_Check(value.ptr())) refuse_type(value, name, "an integer");
  const auto number = py::reinterpret_steal<py::int_>(PyNumber_Index(value.ptr()));
  if (!number) {  // an __index__ that raised (NumPy's bool_)
    PyErr_Clear();
    refuse_type(value, name, "an integer");
  }
  if (number < py::int_(range.min) || number > py::int_(range.max)) {
    throw UserError(whole_number_refusal(name, range, py::str(py::handle(number)).cast<std::string>()));
  }
  return number.cast<std::uint64_t>();
}

double real_number(py::handle value, const std::string& name) {
  if (PyBool_Check(value.ptr()) || is_text(value)) refuse_type(value, name, "a number");
  const double number = PyFloat_AsDouble(value.ptr());
  if (number == -1.0 && PyErr_Occurred()) {  // no __float__, or one that raised
    PyErr_Clear();
    refuse_type(value, name, "a number");
  }
  return number;
}

double positive_number(py::handle value, const std::string& name) {
  const double number = real_number(value, name);
  if (!is_positive_number(number)) throw UserError(positive_number_refusal(name, py::repr(py::float_(number)).cast<std::string>()));
  return number;
}

bool flag(py::handle value, const std::string& name) {
  py::detail::make_caster<bool> caster;
  if (!caster.load(value, /*convert=*/false)) refuse_type(value, name, "True or False");
  return py::detail::cast_op<bool>(caster);
}

std::string word(py::handle value, const std::string& name) {
  if (!PyUnicode_Check(value.ptr())) refuse_type(value, name, "a string");
  Py_ssize_t size = 0;
  const char* text = PyUnicode_AsUTF8AndSize(value.ptr(), &size);
  if (!text) throw py::error_already_set();  // UnicodeEncodeError (a ValueError) names the character
  std::string out(text, std::size_t(size));
  if (out.empty()) throw py::value_error(name + ": an empty value is not allowed (leave it out, or None, for the default)");
  if (out.find('\0') != std::string::npos) throw py::value_error(name + ": embedded null character");
  return out;
}

std::filesystem::path path_argument(py::handle value, const std::string& name) {
  const auto given = py::reinterpret_steal<py::object>(PyOS_FSPath(value.ptr()));
  if (!given) {
    PyErr_Clear();
    throw py::type_error(name + ": expected str, bytes or os.PathLike object, not " + type_name(value));
  }
  const auto bytes = PyBytes_Check(given.ptr()) ? py::reinterpret_borrow<py::bytes>(given)
                                                : py::reinterpret_steal<py::bytes>(PyUnicode_EncodeFSDefault(given.ptr()));
  if (!bytes) throw py::error_already_set();
  const std::string native = bytes;
  if (native.empty()) throw py::value_error(name + ": an empty path is not allowed");
  if (native.find('\0') != std::string::npos) throw py::value_error(name + ": embedded null byte");
  if (const std::string reason = unusable_path_reason(native); !reason.empty()) {
    throw py::value_error(name + ": " + reason);
  }
  return std::filesystem::path(native);
}

py::str path_text(const std::string& native) {
  const auto text = py::reinterpret_steal<py::str>(PyUnicode_DecodeFSDefaultAndSize(native.data(), py::ssize_t(native.size())));
  if (!text) throw py::error_already_set();
  return text;
}

}  // namespace meshparticles::python
