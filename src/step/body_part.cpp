#include "step/body_part.h"

#include <fmt/format.h>

namespace offsetgen::step {

std::string format_body_part(const BodyPart& p) {
  if (p.path.empty()) return "";
  std::string out = fmt::format(
      "  body: {}, {} solid{}, {} faces, {:.6f} mm^3; lattice cells from ({:.4g}, {:.4g}, {:.4g}) mm, the block's "
      "corner at ({:.4g}, {:.4g}, {:.4g}) mm\n",
      p.path, p.body_solids, p.body_solids == 1 ? "" : "s", p.body_faces, p.body_volume, p.origin[0], p.origin[1],
      p.origin[2], p.corner[0], p.corner[1], p.corner[2]);
  if (p.skin > 0)
    out += fmt::format("  skin: {:g} mm, the core (the body offset inward) {:.6f} mm^3\n", p.skin, p.core_volume);
  out += fmt::format(
      "  part ({}): {}, {} solid{} ({} shells, {} closed), {} faces, volume {:.6f} mm^3 ({:.4g}% of the body)\n",
      p.skin > 0 ? "skin and lattice ∩ core" : "lattice ∩ body", p.valid ? "valid (BRepCheck_Analyzer)" : "NOT valid",
      p.solids, p.solids == 1 ? "" : "s", p.shells, p.closed ? "all" : "NOT all", p.faces, p.volume,
      p.body_volume > 0 ? 100 * p.volume / p.body_volume : 0.0);
  if (p.sampled_points > 0)
    out += fmt::format(
        "  sampled without the booleans: {:.2f} mm^3 (standard error {:.2f}; the skin exact, the lattice in the core "
        "at "
        "{} points); the part {:+.3f}%\n",
        p.sampled_volume, p.sampled_error, p.sampled_points,
        p.sampled_volume > 0 ? 100 * (p.volume - p.sampled_volume) / p.sampled_volume : 0.0);
  out += fmt::format(
      "  body time: read {:.2f} s, offset {:.2f} s, booleans {:.2f} s, the part read back and checked {:.2f} s\n",
      p.seconds_read, p.seconds_offset, p.seconds_trim, p.seconds_read_back);
  return out;
}

}  // namespace offsetgen::step
