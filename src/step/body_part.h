// What `offsetgen step --body` measured on the part it wrote: the body read, the block of cells
// placed over it, the core inside the skin, and the part the booleans left (plain C++: the summary's).
#pragma once

#include <array>
#include <string>

namespace offsetgen::step {

struct BodyPart {
  std::string path;
  double skin = 0;                 // mm
  std::array<double, 3> origin{};  // mm: where a lattice cell's corner sits
  std::array<double, 3> corner{};  // mm: the block's lower corner (origin + whole cells)
  std::array<int, 3> cells{};      // the block's cells
  int body_solids = 0, body_faces = 0;
  double body_volume = 0, core_volume = 0;  // mm^3 (core: 0 without a skin)
  int solids = 0, shells = 0, faces = 0;    // of the part
  bool valid = false, closed = false;
  double volume = 0;  // mm^3, of the part
  // The part's volume estimated without the booleans (body_sampling.h): skin exact, lattice sampled.
  double sampled_volume = 0, sampled_error = 0;
  long sampled_points = 0;
  double seconds_read = 0, seconds_offset = 0, seconds_trim = 0, seconds_read_back = 0;
};

// The summary's lines for the part ("" before a body is read).
std::string format_body_part(const BodyPart& part);

}  // namespace offsetgen::step
