// The shader backends' own sin and cos: a snippet calls <prefix>_sin and <prefix>_cos, defined
// ahead of its functions from templates/<lang>/<lang>_trig.in, so its accuracy does not depend on
// the driver's builtins (SwiftShader's sin is off by 1.9e-4; GPUs' fast sin/cos degrade too). The
// names carry the file's prefix: two snippets pasted into one shader each bring their own copy,
// and the include guard keeps a second copy of the same snippet out.
#pragma once

#include <string>
#include <vector>

namespace offsetgen {

// `body` with every sin( and cos( call renamed to <prefix>_sin( and <prefix>_cos(.
std::string call_own_trig(const std::string& body, const std::string& prefix);

// `functions` preceded by the helpers of `trig_template` ("glsl/glsl_trig.in") when they call them.
std::string with_own_trig(const std::string& functions, const std::string& prefix, const std::string& trig_template);

// The helpers' names, for Backend::declared_identifiers.
std::vector<std::string> own_trig_names(const std::string& prefix);

}  // namespace offsetgen
