// Running a generated NumPy module (<prefix>.py) for `offsetgen check`: python3 loads it from its
// path and evaluates one function over arrays of inputs. Data goes through float64 files, so no
// digit is lost on the way.
#pragma once

#include <string>
#include <vector>

namespace offsetgen::run::numpy {

// `python` is check::find_python()'s (plot.h). Returns "/usr/bin/python3 with NumPy 1.24.2"; throws
// std::runtime_error naming what to install when python3 or NumPy is missing.
std::string describe_python(const std::string& python);

// Loads the module (throws std::runtime_error with python's message when it does not import).
void import_module(const std::string& python, const std::string& module_path);

// <prefix>_<function>(*columns): each column is one argument over all points (equal lengths);
// returns points * components values, point-major (the normal's tuple stacked per point). Throws
// std::runtime_error when python fails.
std::vector<double> run(const std::string& python, const std::string& module_path, const std::string& function,
                        const std::vector<std::vector<double>>& columns, int components);

}  // namespace offsetgen::run::numpy
