#include "step/body_trim.h"

#include "step/wall_brep.h"
#include "support/stopwatch.h"

#include <fmt/format.h>
#include <BRepAlgoAPI_BooleanOperation.hxx>
#include <BRepAlgoAPI_Common.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <BRepClass3d.hxx>
#include <BRepClass3d_SolidClassifier.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Iterator.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Solid.hxx>
#include <gp_Trsf.hxx>

#include <algorithm>
#include <array>
#include <filesystem>
#include <stdexcept>
#include <utility>
#include <vector>

namespace offsetgen::step {
namespace {

// One boolean, on every core.
TopoDS_Shape run_boolean(BRepAlgoAPI_BooleanOperation&& op, const TopoDS_Shape& object, const TopoDS_Shape& tool,
                         const char* what) {
  TopTools_ListOfShape objects, tools;
  objects.Append(object);
  tools.Append(tool);
  op.SetArguments(objects);
  op.SetTools(tools);
  op.SetRunParallel(Standard_True);
  // The arguments are known to be outward-oriented solids (the block is built so and measured, the
  // body and core are checked for a positive volume), so OpenCASCADE's test for inverted solids, a
  // point classified against each whole solid (2-3 s on the 3,840-face lattice), is skipped.
  op.SetCheckInverted(Standard_False);
  op.Build();
  if (!op.IsDone() || op.HasErrors())
    throw std::runtime_error(fmt::format("OpenCASCADE's boolean ({}) failed on the lattice and the body", what));
  return op.Shape();
}

// A face's place in a canonical order: its bounding box, corner by corner. OpenCASCADE's parallel
// booleans hand back the faces of a shell in an order that changes from run to run; the file's bytes
// must not.
std::array<double, 6> face_key(const TopoDS_Shape& face) {
  Bnd_Box box;
  BRepBndLib::Add(face, box, /*useTriangulation=*/Standard_False);
  std::array<double, 6> key{};
  box.Get(key[0], key[1], key[2], key[3], key[4], key[5]);
  return key;
}

// The shell with its faces in the canonical order (the same faces, orientations and closure).
TopoDS_Shell canonical_shell(const TopoDS_Shape& shell) {
  std::vector<std::pair<std::array<double, 6>, TopoDS_Shape>> faces;
  for (TopoDS_Iterator f(shell); f.More(); f.Next()) faces.emplace_back(face_key(f.Value()), f.Value());
  std::stable_sort(faces.begin(), faces.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  BRep_Builder builder;
  TopoDS_Shell out;
  builder.MakeShell(out);
  for (const auto& face : faces) builder.Add(out, face.second);
  out.Closed(BRep_Tool::IsClosed(shell));
  return TopoDS::Shell(out.Oriented(shell.Orientation()));
}

// The result's solids in one compound (a boolean's result may nest compounds).
TopoDS_Shape solids_of(const TopoDS_Shape& shape) {
  TopoDS_Compound out;
  BRep_Builder builder;
  builder.MakeCompound(out);
  for (TopExp_Explorer e(shape, TopAbs_SOLID); e.More(); e.Next()) {
    TopoDS_Solid solid;
    builder.MakeSolid(solid);
    for (TopoDS_Iterator shell(e.Current()); shell.More(); shell.Next())
      builder.Add(solid, canonical_shell(shell.Value()));
    builder.Add(out, solid.Oriented(e.Current().Orientation()));
  }
  return out;
}

// The solids with the pores taken out, each pore inside one of them: a pore's outer shell, reversed,
// is a void of the solid around it; an inner shell of a pore bounds a piece of lattice that floats in
// it, a solid of its own (that shell reversed).
TopoDS_Shape with_voids(const TopoDS_Shape& solids, const TopoDS_Shape& pores) {
  BRep_Builder builder;
  std::vector<TopoDS_Shape> around;  // the solids as read, to classify the pores against
  std::vector<TopoDS_Solid> out;     // the same shells, and the voids
  for (TopExp_Explorer e(solids, TopAbs_SOLID); e.More(); e.Next()) {
    around.push_back(e.Current());
    TopoDS_Solid copy;
    builder.MakeSolid(copy);
    for (TopoDS_Iterator shell(e.Current()); shell.More(); shell.Next()) builder.Add(copy, shell.Value());
    out.push_back(copy);
  }
  std::vector<std::pair<std::array<double, 6>, TopoDS_Solid>> in_order;
  for (TopExp_Explorer e(pores, TopAbs_SOLID); e.More(); e.Next())
    in_order.emplace_back(face_key(e.Current()), TopoDS::Solid(e.Current()));
  std::stable_sort(in_order.begin(), in_order.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<TopoDS_Solid> islands;
  for (const auto& [key, pore] : in_order) {
    const TopoDS_Shell outer = BRepClass3d::OuterShell(pore);
    if (outer.IsNull()) throw std::runtime_error("a pore (core - lattice) has no outer shell");
    const gp_Pnt at = BRep_Tool::Pnt(TopoDS::Vertex(TopExp_Explorer(outer, TopAbs_VERTEX).Current()));
    size_t inside = 0;
    while (inside < around.size() && BRepClass3d_SolidClassifier(around[inside], at, 1e-7).State() != TopAbs_IN)
      ++inside;
    if (inside == around.size()) throw std::runtime_error("a pore (core - lattice) lies outside the body");
    builder.Add(out[inside], canonical_shell(outer).Reversed());
    for (TopoDS_Iterator shell(pore); shell.More(); shell.Next()) {
      if (shell.Value().IsSame(outer)) continue;
      TopoDS_Solid island;
      builder.MakeSolid(island);
      builder.Add(island, canonical_shell(shell.Value()).Reversed());
      islands.push_back(island);
    }
  }
  TopoDS_Compound compound;
  builder.MakeCompound(compound);
  for (const TopoDS_Solid& solid : out) builder.Add(compound, solid);
  for (const TopoDS_Solid& solid : islands) builder.Add(compound, solid);
  return compound;
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
    result = solids_of(run_boolean(BRepAlgoAPI_Common(), placed, body.solids, "lattice ∩ body"));
  } else {
    // skin ∪ (lattice ∩ core) is the body less the pores, core - lattice: one boolean where the skin's
    // cut and fuse took two more, the fuse a pass over every face of the lattice (the holed box's:
    // 4-5 s). The pores lie inside the core, so they are the body's voids as they are.
    say("trimming: the pores, core - lattice");
    const TopoDS_Shape pores = run_boolean(BRepAlgoAPI_Cut(), body.core, placed, "core - lattice");
    say("trimming: the body with the pores as voids");
    result = with_voids(body.solids, pores);
  }
  part.seconds_trim = seconds_since(t0);
  return result;
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
