#include "emit/shader_trig.h"

#include "emit/c_batch.h"
#include "emit/templates.h"

#include <fmt/format.h>

namespace offsetgen {

std::string call_own_trig(const std::string& body, const std::string& prefix) {
  return rename_trig_calls(body, prefix + "_");
}

std::string with_own_trig(const std::string& functions, const std::string& prefix, const std::string& trig_template) {
  if (functions.find(prefix + "_sin(") == std::string::npos && functions.find(prefix + "_cos(") == std::string::npos)
    return functions;
  const auto sections = load_template_sections(trig_template, {"trig"});
  return fmt::format(fmt::runtime(sections.at("trig")), fmt::arg("prefix", prefix)) + functions;
}

std::vector<std::string> own_trig_names(const std::string& prefix) { return {prefix + "_sin", prefix + "_cos"}; }

}  // namespace offsetgen
