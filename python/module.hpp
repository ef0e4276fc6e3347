#pragma once
// What the files of the extension module cyclic_triax._engine share: its exceptions (made in
// engine_module.cpp's PYBIND11_MODULE) and the functions that add each part's bindings.
#include <pybind11/pybind11.h>

#include <string>

namespace ct_python {

extern PyObject* config_error;       // bad input: nothing was written (a ValueError)
extern PyObject* output_path_error;  // where the result may not go: nothing was run
extern PyObject* run_error;          // the run failed

// Sets the Python exception `type` with `message` and throws to pybind11, which raises it.
[[noreturn]] void raise(PyObject* type, const std::string& message);

void bind_study(pybind11::module_& m);        // study_module.cpp: the pipeline's plan and run, validate
void bind_calibration(pybind11::module_& m);  // calibration_adapter.cpp: calibrate

}  // namespace ct_python
