#include "cli/step_body_options.h"

namespace offsetgen {

void add_step_body_options(CLI::App* cmd, BodyOptions& o) {
  CLI::Option* body = cmd->add_option(
      "-b,--body", o.body,
      "Trim the lattice by this part instead of writing a block: a closed solid as STEP (.step, .stp) or BREP "
      "(.brep), in millimetres; the block of cells covers it (a mesh body is refused: the booleans need a B-rep)");
  cmd->add_option("--skin", o.skin,
                  "With --body: a solid skin this thick (mm) inward from the body's surface (OpenCASCADE's offset); "
                  "the lattice fills the core inside it and joins it (0: the lattice cut flush by the body)")
      ->capture_default_str()
      ->needs(body);
  cmd->add_option("--origin", o.origin,
                  "With --body: X,Y,Z (mm) where a lattice cell's corner sits (default the body's bounding-box "
                  "minimum), as in `offsetgen mesh --body`")
      ->needs(body);
  cmd->add_option("--scale", o.scale, "With --body: multiply its coordinates (25.4 for inches, 1000 for metres)")
      ->capture_default_str()
      ->needs(body);
}

}  // namespace offsetgen
