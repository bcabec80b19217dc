#include "step/body_trim.h"

#include "step/wall_brep.h"
#include "support/stopwatch.h"

#include <fmt/format.h>
#include <BRepAlgoAPI_BooleanOperation.hxx>
#include <BRepAlgoAPI_Common.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <BRep_Builder.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS_Compound.hxx>
#include <gp_Trsf.hxx>

#include <filesystem>
#include <stdexcept>

namespace offsetgen::step {
namespace {

// One boolean, on every core.
TopoDS_Shape run_boolean(BRepAlgoAPI_BooleanOperation&& op, const TopoDS_Shape& object, const TopoDS_Shape& tool,
                         const char* what, BOPAlgo_GlueEnum glue = BOPAlgo_GlueOff) {
  TopTools_ListOfShape objects, tools;
  objects.Append(object);
  tools.Append(tool);
  op.SetArguments(objects);
  op.SetTools(tools);
  op.SetRunParallel(Standard_True);
  op.SetGlue(glue);
  // The arguments are known to be outward-oriented solids (the block is built so and measured, the
  // body and core are checked for a positive volume), so OpenCASCADE's test for inverted solids, a
  // point classified against each whole solid (2-3 s on the 3,840-face lattice), is skipped.
  op.SetCheckInverted(Standard_False);
  op.Build();
  if (!op.IsDone() || op.HasErrors())
    throw std::runtime_error(fmt::format("OpenCASCADE's boolean ({}) failed on the lattice and the body", what));
  return op.Shape();
}

// The result's solids in one compound (a boolean's result may nest compounds).
TopoDS_Shape solids_of(const TopoDS_Shape& shape) {
  TopoDS_Compound out;
  BRep_Builder builder;
  builder.MakeCompound(out);
  for (TopExp_Explorer e(shape, TopAbs_SOLID); e.More(); e.Next()) builder.Add(out, e.Current());
  return out;
}

}  // namespace

TopoDS_Shape trim_by_body(const TopoDS_Shape& lattice, const CadBody& body, BodyPart& part,
                          const std::function<void(const std::string&)>& say) {
  const auto t0 = Clock::now();
  gp_Trsf move;
  move.SetTranslation(gp_Vec(body.corner[0], body.corner[1], body.corner[2]));
  const TopoDS_Shape placed = BRepBuilderAPI_Transform(lattice, move, /*copy=*/Standard_False).Shape();
  TopoDS_Shape result;
  if (body.core.IsNull()) {
    say("trimming: lattice ∩ body");
    result = run_boolean(BRepAlgoAPI_Common(), placed, body.solids, "lattice ∩ body");
  } else {
    say("trimming: the skin, body - core");
    const TopoDS_Shape skin = run_boolean(BRepAlgoAPI_Cut(), body.solids, body.core, "body - core");
    say("trimming: lattice ∩ core");
    const TopoDS_Shape inner = run_boolean(BRepAlgoAPI_Common(), placed, body.core, "lattice ∩ core");
    say("trimming: skin ∪ (lattice ∩ core)");
    // The two only touch, on the core's surface, where their faces coincide in part: glue mode skips
    // intersecting the lattice's faces with the skin's (the holed box's booleans: 43 s -> 27 s, the
    // same solid and volume).
    result = run_boolean(BRepAlgoAPI_Fuse(), skin, inner, "skin ∪ (lattice ∩ core)", BOPAlgo_GlueShift);
  }
  const TopoDS_Shape part_solids = solids_of(result);
  part.seconds_trim = seconds_since(t0);
  return part_solids;
}

void measure_part(const TopoDS_Shape& shape, BodyPart& part) {
  const ShapeCheck c = check_shape(shape);
  part.valid = c.valid;
  part.closed = c.closed;
  part.solids = c.solids;
  part.shells = c.shells;
  part.faces = c.faces;
  part.volume = c.volume;
}

std::string body_part_failure(const BodyPart& p) {
  if (p.valid && p.closed && p.solids > 0 && p.shells >= p.solids && p.volume > 0) return "";
  return fmt::format(
      "the part trimmed by the body is not valid closed solids (valid {}, solids {}, shells {}, closed {}, volume "
      "{:.6g} mm^3)",
      p.valid, p.solids, p.shells, p.closed, p.volume);
}

std::string body_part_description(const StepRequest& r, const StepSummary& s) {
  return fmt::format(
      "offsetgen: {} wall, t = {} (cell units), cells of {} mm from ({}, {}, {}) mm, tolerance {} mm, "
      "{} by the body {}{}",
      s.surface, s.thickness_text, r.cell_size[0], s.body.origin[0], s.body.origin[1], s.body.origin[2], r.tolerance,
      s.body.skin > 0 ? "with a skin, trimmed" : "trimmed", std::filesystem::path(s.body.path).filename().string(),
      s.body.skin > 0 ? fmt::format(", skin {} mm", s.body.skin) : "");
}

}  // namespace offsetgen::step
