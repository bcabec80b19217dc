// The file skeletons (templates/<lang>/*.in) compiled into the executable. The table is generated at
// build time by cmake/EmbedTemplates.cmake; templates.h reads it.
#pragma once

#include <string_view>
#include <vector>

namespace offsetgen {

struct EmbeddedTemplate {
  std::string_view name;  // path under templates/, e.g. "c/c_header.h.in"
  std::string_view text;
};

// Every template, sorted by name.
const std::vector<EmbeddedTemplate>& embedded_templates();

}  // namespace offsetgen
