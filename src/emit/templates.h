// Finds and reads the skeletons of emitted files (templates/<lang>/*.in), which are rendered with fmt.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace offsetgen {

// Search order: $OFFSETGEN_TEMPLATE_DIR, <executable>/../share/offsetgen/templates (installed),
// <executable>/share/offsetgen/templates (the build tree's copy beside the built offsetgen), and for
// test executables only the source tree's templates/. Throws std::runtime_error naming the paths
// tried.
std::string load_template(const std::string& name);

// A template holding several skeletons, each introduced by a line "@@ <name>"; text before the first
// such line is a comment. Throws std::runtime_error if a section in `required` is missing.
std::map<std::string, std::string> load_template_sections(const std::string& name,
                                                          const std::vector<std::string>& required);

// The directory load_template reads from (for --version and diagnostics).
std::string template_directory();

}  // namespace offsetgen
