// The lattice of `offsetgen step --body` trimmed by the body with OpenCASCADE's booleans: lattice ∩
// body without a skin; with one, body - (core - lattice), which is skin ∪ (lattice ∩ core) and asks no
// boolean to merge coincident faces (the pores lie inside the body, at the skin's depth).
#pragma once

#include "step/body_part.h"
#include "step/body_solid.h"
#include "step/step_request.h"
#include "step/step_summary.h"

#include <TopoDS_Shape.hxx>

#include <functional>
#include <string>

namespace offsetgen::step {

// `lattice` in block coordinates (mm from the block's corner). The part: a compound of its solids,
// one per connected piece; its checks (BRepCheck_Analyzer, closed shells, volume) recorded in `part`.
// Throws std::runtime_error where a boolean fails.
TopoDS_Shape trim_by_body(const TopoDS_Shape& lattice, const CadBody& body, BodyPart& part,
                          const std::function<void(const std::string&)>& say);

// "" when the part is valid closed solids, else what fails.
std::string body_part_failure(const BodyPart& part);

// The header's description of a part: for people only. It carries no offsetgen-metadata, since
// `offsetgen check` rebuilds a block's walls and a part is no block: export measures the part.
std::string body_part_description(const StepRequest& request, const StepSummary& summary);

}  // namespace offsetgen::step
