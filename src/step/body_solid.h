// The CAD body of `offsetgen step --body`: a STEP or BREP file read as closed, valid solids; the block
// of whole cells, counted from --origin, that covers it; and the core inside its skin, by
// OpenCASCADE's offset algorithm.
#pragma once

#include "body/body_request.h"
#include "step/body_part.h"

#include <TopoDS_Shape.hxx>

#include <array>
#include <string>

namespace offsetgen::step {

// InputError for a body the booleans cannot take, found before any work: a mesh file (STL, PLY, OBJ,
// 3MF: no B-rep), a name that is neither STEP nor BREP, --fillet or --repair (mesh's options), or
// what body::validate_body refuses.
void validate_cad_body(const body::BodyRequest& request, const std::string& output);

struct CadBody {
  TopoDS_Shape solids;             // the body, scaled: its solids (a compound where there are several)
  TopoDS_Shape core;               // the solids offset inward by the skin; null without a skin
  std::array<int, 3> cells{};      // the block over the body's box
  std::array<double, 3> corner{};  // mm: the block's lower corner, origin + whole cells
};

// Reads the body, checks it (valid, closed solids, large enough for a cell and the skin), places the
// block (whole cells of the given sides, mm: a cube or a box cell) and offsets the core; records what it measured in
// `part`. InputError where the file holds no closed valid solid or the inward offset fails or leaves no core.
CadBody load_cad_body(const body::BodyRequest& request, const std::array<double, 3>& cell_size, BodyPart& part);

}  // namespace offsetgen::step
