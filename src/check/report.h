// The check's output: a readable table (stdout), every number as JSON (--json), and the input of
// tools/plot_convergence.py (--plot).
#pragma once

#include "check/check.h"

#include <nlohmann/json.hpp>

#include <string>

namespace offsetgen::check {

std::string format_report(const CheckReport& report);
nlohmann::ordered_json report_json(const CheckReport& report);
// Error against h/L, one series per measurement, slope triangles at the expected orders.
nlohmann::json plot_spec(const CheckReport& report);

}  // namespace offsetgen::check
