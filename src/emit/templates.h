// Reads the skeletons of emitted files (templates/<lang>/*.in), which are rendered with fmt. They are
// compiled into the executable (emit/embedded_templates.h), so an installed offsetgen is one file and
// always renders with the templates it was built with.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace offsetgen {

// The text of templates/<name>, e.g. "c/c_header.h.in". Throws std::runtime_error for a name that
// was not compiled in (a programming error: backends name their own templates).
std::string load_template(const std::string& name);

// A template holding several skeletons, each introduced by a line "@@ <name>"; text before the first
// such line is a comment. Throws std::runtime_error if a section in `required` is missing.
std::map<std::string, std::string> load_template_sections(const std::string& name,
                                                          const std::vector<std::string>& required);

}  // namespace offsetgen
