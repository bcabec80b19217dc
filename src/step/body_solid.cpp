#include "step/body_solid.h"

#include "step/step_file.h"
#include "support/stopwatch.h"
#include "surfaces/input_error.h"

#include <fmt/format.h>
#include <BRepAlgoAPI_Common.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeSolid.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepGProp.hxx>
#include <BRepOffsetAPI_MakeOffsetShape.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <GProp_GProps.hxx>
#include <ShapeAnalysis_FreeBounds.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <gp_Trsf.hxx>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <vector>

namespace offsetgen::step {
namespace {

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

int count(const TopoDS_Shape& shape, TopAbs_ShapeEnum type) {
  int n = 0;
  for (TopExp_Explorer e(shape, type); e.More(); e.Next()) ++n;
  return n;
}

double volume_of(const TopoDS_Shape& shape) {
  GProp_GProps props;
  BRepGProp::VolumeProperties(shape, props);
  return props.Mass();
}

TopoDS_Shape read_cad_file(const std::string& path) {
  if (!std::filesystem::is_regular_file(path)) throw InputError(fmt::format("--body {}: no such file", path));
  TopoDS_Shape shape;
  if (lower_extension(path) == ".brep") {
    BRep_Builder builder;
    if (!BRepTools::Read(shape, path.c_str(), builder) || shape.IsNull())
      throw InputError(fmt::format("--body {}: not a BREP file OpenCASCADE can read", path));
    return shape;
  }
  try {
    return read_step(path);
  } catch (const std::runtime_error& e) {
    throw InputError(fmt::format("--body {}: {}", path, e.what()));
  }
}

// The file's solids in one compound; InputError for a file without a closed valid solid.
TopoDS_Shape closed_solids(const TopoDS_Shape& shape, const std::string& path) {
  TopoDS_Compound solids;
  BRep_Builder builder;
  builder.MakeCompound(solids);
  int n = 0;
  for (TopExp_Explorer e(shape, TopAbs_SOLID); e.More(); e.Next(), ++n) {
    for (TopExp_Explorer s(e.Current(), TopAbs_SHELL); s.More(); s.Next())
      if (!BRep_Tool::IsClosed(s.Current()))
        throw InputError(fmt::format(
            "--body {}: a solid of it is bounded by an open shell, so it has no inside; close it in your CAD tool",
            path));
    builder.Add(solids, e.Current());
  }
  if (n == 0) {
    // Faces or shells only: say how open they are.
    ShapeAnalysis_FreeBounds bounds(shape);
    const int open_wires = count(bounds.GetOpenWires(), TopAbs_WIRE) + count(bounds.GetClosedWires(), TopAbs_WIRE);
    throw InputError(fmt::format(
        "--body {}: holds no solid ({} faces in {} shells{}): the lattice is trimmed by a solid's inside; give a "
        "closed solid",
        path, count(shape, TopAbs_FACE), count(shape, TopAbs_SHELL),
        open_wires > 0 ? fmt::format(", {} free boundaries: an open surface", open_wires) : ""));
  }
  if (!BRepCheck_Analyzer(solids).IsValid())
    throw InputError(fmt::format(
        "--body {}: OpenCASCADE's BRepCheck_Analyzer finds the body not valid (checkshape in occt-draw says where); "
        "repair it in your CAD tool",
        path));
  std::vector<TopoDS_Shape> each;
  for (TopExp_Explorer e(solids, TopAbs_SOLID); e.More(); e.Next()) {
    if (!(volume_of(e.Current()) > 0))
      throw InputError(fmt::format(
          "--body {}: a solid of it has no positive volume (its faces point inward); fix it in your CAD tool", path));
    each.push_back(e.Current());
  }
  // Overlapping solids (two bodies in one file) would each be offset and trimmed on its own: the
  // booleans then keep neither the lattice nor the skin where they overlap.
  for (size_t i = 0; i < each.size(); ++i)
    for (size_t j = i + 1; j < each.size(); ++j) {
      BRepAlgoAPI_Common common(each[i], each[j]);
      if (common.IsDone() && volume_of(common.Shape()) > 1e-9 * std::min(volume_of(each[i]), volume_of(each[j])))
        throw InputError(
            fmt::format("--body {}: solids {} and {} of it overlap; fuse them into one solid in your CAD tool", path,
                        i + 1, j + 1));
    }
  return solids;
}

std::array<std::array<double, 3>, 2> box_of(const TopoDS_Shape& shape) {
  Bnd_Box box;
  BRepBndLib::AddOptimal(shape, box, /*useTriangulation=*/false, /*useShapeTolerance=*/false);
  double x0, y0, z0, x1, y1, z1;
  box.Get(x0, y0, z0, x1, y1, z1);
  return {{{x0, y0, z0}, {x1, y1, z1}}};
}

// The body offset inward by `skin`, solid by solid: arcs at concave edges, so that the core is the points
// farther than the skin from the surface, as mesh's skin is.
TopoDS_Shape inward_offset(const TopoDS_Shape& solids, double skin, const std::string& path) {
  TopoDS_Compound core;
  BRep_Builder builder;
  builder.MakeCompound(core);
  auto refuse = [&](const std::string& why) {
    return InputError(fmt::format(
        "--skin {:g}: OpenCASCADE's offset (BRepOffsetAPI_MakeOffsetShape) cannot offset {} inward by {:g} mm: {}; "
        "try a thinner skin, or --skin 0",
        skin, path, skin, why));
  };
  for (TopExp_Explorer e(solids, TopAbs_SOLID); e.More(); e.Next()) {
    TopoDS_Shape shape;
    try {
      BRepOffsetAPI_MakeOffsetShape offset;
      offset.PerformByJoin(e.Current(), -skin, 1e-7, BRepOffset_Skin, Standard_False, Standard_False, GeomAbs_Arc);
      if (!offset.IsDone()) throw refuse(fmt::format("it stops with error {}", int(offset.MakeOffset().Error())));
      shape = offset.Shape();
    } catch (const Standard_Failure& f) {
      throw refuse(fmt::format("{}: {}", f.DynamicType()->Name(), f.GetMessageString()));
    }
    int solids_made = 0;
    for (TopExp_Explorer s(shape, TopAbs_SOLID); s.More(); s.Next(), ++solids_made) builder.Add(core, s.Current());
    if (solids_made == 0)
      for (TopExp_Explorer s(shape, TopAbs_SHELL); s.More(); s.Next(), ++solids_made) {
        if (!BRep_Tool::IsClosed(s.Current())) throw refuse("the offset surface is not closed");
        builder.Add(core, BRepBuilderAPI_MakeSolid(TopoDS::Shell(s.Current())).Solid());
      }
    if (solids_made == 0) throw InputError(fmt::format("--skin {:g} mm leaves no core for the lattice", skin));
  }
  if (!BRepCheck_Analyzer(core).IsValid()) throw refuse("the offset solid is not valid (BRepCheck_Analyzer)");
  const double body = volume_of(solids), inside = volume_of(core);
  if (!(inside > 0))
    throw InputError(fmt::format("--skin {:g} mm leaves no core for the lattice (the offset has no volume)", skin));
  if (!(inside < body)) throw refuse("the offset is not inside the body");
  return core;
}

}  // namespace

void validate_cad_body(const body::BodyRequest& r, const std::string& output) {
  const std::string ext = lower_extension(r.path);
  if (ext == ".stl" || ext == ".ply" || ext == ".obj" || ext == ".3mf")
    throw InputError(fmt::format(
        "--body {}: a mesh body. STEP export trims the lattice's B-spline faces by the body with B-rep booleans, "
        "which need a B-rep body: give it as STEP (.step, .stp) or BREP (.brep), or fill the mesh with "
        "`offsetgen mesh --body`",
        r.path));
  if (ext != ".step" && ext != ".stp" && ext != ".brep")
    throw InputError(fmt::format("--body {}: give the body as STEP (.step, .stp) or BREP (.brep)", r.path));
  if (r.fillet > 0) throw InputError("--fillet: offsetgen step does not blend the walls into the skin");
  if (r.repair) throw InputError("--repair mends mesh bodies; repair a STEP body in your CAD tool");
  body::validate_body(r, output);
}

CadBody load_cad_body(const body::BodyRequest& r, const std::array<double, 3>& cell_size, BodyPart& part) {
  auto t0 = Clock::now();
  CadBody out;
  TopoDS_Shape shape = read_cad_file(r.path);
  if (r.scale != 1) {
    gp_Trsf scale;
    scale.SetScale(gp_Pnt(0, 0, 0), r.scale);
    shape = BRepBuilderAPI_Transform(shape, scale, /*copy=*/Standard_True).Shape();
  }
  out.solids = closed_solids(shape, r.path);
  part.path = r.path;
  part.skin = r.skin;
  part.body_solids = count(out.solids, TopAbs_SOLID);
  part.body_faces = count(out.solids, TopAbs_FACE);
  part.body_volume = volume_of(out.solids);
  const auto box = box_of(out.solids);
  body::check_body_size(box, *std::min_element(cell_size.begin(), cell_size.end()), r.skin);
  part.seconds_read = seconds_since(t0);

  t0 = Clock::now();
  auto lattice_box = box;
  if (r.skin > 0) {
    out.core = inward_offset(out.solids, r.skin, r.path);
    part.core_volume = volume_of(out.core);
    lattice_box = box_of(out.core);  // the lattice need only fill the core
  }
  part.seconds_offset = seconds_since(t0);

  // Whole cells from the origin, so that the walls sit where `mesh --body --origin` puts them.
  part.origin = r.origin ? *r.origin : box[0];
  for (size_t a = 0; a < 3; ++a) {
    constexpr double kSlack = 1e-9;  // a box side on a cell plane takes no extra cell
    const double lo = std::floor((lattice_box[0][a] - part.origin[a]) / cell_size[a] + kSlack);
    const double hi = std::ceil((lattice_box[1][a] - part.origin[a]) / cell_size[a] - kSlack);
    out.cells[a] = std::max(1, int(hi - lo));
    out.corner[a] = part.origin[a] + lo * cell_size[a];
  }
  part.corner = out.corner;
  part.cells = out.cells;
  return out;
}

}  // namespace offsetgen::step
