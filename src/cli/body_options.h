// The body option group, shared by `mesh` and `slice`: --body, --skin, --fillet, --origin, --scale,
// --repair, and the body request they make.
#pragma once

#include "body/body_request.h"

#include <CLI/CLI.hpp>

#include <array>
#include <optional>
#include <string>

namespace offsetgen {

struct BodyOptions {
  std::string body, origin;  // --body FILE, --origin X,Y,Z
  double skin = 0, fillet = 0, scale = 1;
  bool repair = false;
};

// Adds the group to `cmd`; returns the --body option (for excludes and needs).
CLI::Option* add_body_options(CLI::App* cmd, BodyOptions& options);
// The request the options make; nullopt without --body. Throws InputError for a bad --origin.
std::optional<body::BodyRequest> body_request(const BodyOptions& options);

// "1,2.5,-3" -> {1, 2.5, -3} (--origin). Throws InputError naming `option`.
std::array<double, 3> parse_point(const std::string& text, const std::string& option);

}  // namespace offsetgen
