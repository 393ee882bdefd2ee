// The error mapping of the Python binding (see py_support.h): the core's and the library's
// exceptions become the hedge._errors class of their kind.
#include <exception>
#include <new>
#include <stdexcept>

#include "binding/errors.h"
#include "hedge/error.h"
#include "py_support.h"

namespace hedge::python {

namespace {

//! Raises the hedge._errors class of `kind` with this message and refusal (null: none).
void raise(const char* kind, const char* message, const char* refusal) {
  // Looked up at each error: errors are rare, and the module holds no Python object past the
  // interpreter's end this way.
  const py::module_ errors = py::module_::import("hedge._errors");
  const py::object cls = errors.attr("BY_KIND").attr("get")(kind, errors.attr("InternalError"));
  const py::object why = refusal != nullptr && *refusal != '\0' ? py::object(py::str(refusal)) : py::none();
  const py::object error = cls(py::str(message), why);
  PyErr_SetObject(cls.ptr(), error.ptr());
}

//! Raises the failure of the exception being handled (binding::current_failure). In a catch only.
void raise_current() {
  const binding::Failure f = binding::current_failure();
  raise(binding::kind_name(f.status), f.message, f.refusal);
}

void translate(std::exception_ptr p) {
  try {
    std::rethrow_exception(p);
  } catch (const ViewsExported& e) {
    raise("views-exported", e.message.c_str(), nullptr);
  } catch (const binding::BindingError&) {
    raise_current();
  } catch (const hedge::Error&) {
    raise_current();
  } catch (const std::bad_alloc&) {
    raise_current();
  } catch (const std::length_error&) {
    raise_current();
  }
  // Anything else (pybind11's own exceptions, error_already_set) propagates to pybind11's
  // translators.
}

}  // namespace

void require_no_views(const State& state, const std::string& what) {
  if (state.views > 0)
    throw ViewsExported{
        what + ": " + std::to_string(state.views) +
        " numpy view(s) of the mesh's arrays are alive, and adding elements may move the "
        "arrays under them; delete the views first (nothing was changed). A view may also be kept "
        "alive by the REPL's `_` or a notebook's Out[]: `del` it, or call gc.collect()"};
}

std::uint32_t element_index(std::int64_t i, const char* kind) {
  if (i < 0 || i > 0xfffffffeLL)
    binding::fail(HEDGE_ERROR_BAD_HANDLE, std::string(kind) + " " + std::to_string(i) + " is out of range");
  return static_cast<std::uint32_t>(i);
}

void register_errors() { py::register_exception_translator(translate); }

}  // namespace hedge::python
