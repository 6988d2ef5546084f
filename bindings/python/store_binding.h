#pragma once
// kumite.Store: the training store (authoring/training/training_store.h) read from Python, its tables as pandas
// DataFrames, or as dicts of numpy arrays where pandas is not installed.

#include <pybind11/pybind11.h>

namespace kumite::python {

// Adds kumite.Store to the module; its errors raise the module's kumite.Error, which must be registered already.
void bind_store(pybind11::module_& module);

} // namespace kumite::python
