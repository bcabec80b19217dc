// --plot: the log-log convergence figure, drawn by tools/plot_convergence.py (matplotlib).
#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace offsetgen::check {

// The plot script: `explicit_path` (--plot-script) if given, else $OFFSETGEN_PLOT_SCRIPT, else
// <dir of the running executable>/../share/offsetgen/tools/plot_convergence.py (installed), else
// the source tree's tools/plot_convergence.py. "" when none exists.
std::string find_plot_script(const std::string& explicit_path);

// Writes `spec` (plot_convergence.py's input schema) to a scratch file and renders `png`.
// Throws InputError with the script's output when it cannot.
void render_plot(const nlohmann::json& spec, const std::string& png, const std::string& script);

}  // namespace offsetgen::check
