#include "step/wall_brep.h"

#include "step/cell_symmetry.h"

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeSolid.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepGProp.hxx>
#include <BRepLib.hxx>
#include <BRep_Tool.hxx>
#include <GProp_GProps.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <ShapeUpgrade_UnifySameDomain.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Solid.hxx>
#include <gp_Pln.hxx>

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

namespace offsetgen::step {
namespace {

struct Placement {
  const CellImage* image;
  std::array<int, 3> cell;
  double cell_size;
  gp_Pnt operator()(const Point& p) const {
    const Point q = image->apply(p);
    return gp_Pnt((q[0] + cell[0]) * cell_size, (q[1] + cell[1]) * cell_size, (q[2] + cell[2]) * cell_size);
  }
};

void knots_of(int n, TColStd_Array1OfReal& knots, TColStd_Array1OfInteger& mults) {
  const CubicKnots k(n);
  knots.Resize(1, static_cast<int>(k.distinct.size()), false);
  mults.Resize(1, static_cast<int>(k.distinct.size()), false);
  for (size_t i = 0; i < k.distinct.size(); ++i) {
    knots.SetValue(static_cast<int>(i) + 1, k.distinct[i]);
    mults.SetValue(static_cast<int>(i) + 1, k.multiplicities[i]);
  }
}

TopoDS_Face patch_face(const CubicPatch& patch, const Placement& place) {
  const int n = patch.n;
  TColgp_Array2OfPnt poles(1, n, 1, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) poles.SetValue(i + 1, j + 1, place(patch.at(i, j)));
  TColStd_Array1OfReal knots(1, 2);
  TColStd_Array1OfInteger mults(1, 2);
  knots_of(n, knots, mults);
  Handle(Geom_BSplineSurface) surface = new Geom_BSplineSurface(poles, knots, knots, mults, mults, 3, 3);
  BRepBuilderAPI_MakeFace face(surface, Precision::Confusion());
  if (!face.IsDone()) throw std::runtime_error("STEP: BRepBuilderAPI_MakeFace failed on a B-spline patch");
  return face.Face();
}

// The v = 0 boundary of a patch (on the plane z = 0), placed.
TopoDS_Edge boundary_edge(const CubicPatch& patch, const Placement& place) {
  const int n = patch.n;
  TColgp_Array1OfPnt poles(1, n);
  for (int i = 0; i < n; ++i) poles.SetValue(i + 1, place(patch.at(i, 0)));
  TColStd_Array1OfReal knots(1, 2);
  TColStd_Array1OfInteger mults(1, 2);
  knots_of(n, knots, mults);
  Handle(Geom_BSplineCurve) curve = new Geom_BSplineCurve(poles, knots, mults, 3);
  return BRepBuilderAPI_MakeEdge(curve).Edge();
}

// The cap between the two sheets' v = 0 boundaries on a face of the block: a planar quadrilateral
// (the two curves and two segments on the mirror lines x = y and x = 1/2 of that plane).
TopoDS_Face cap_face(const CubicPatch& plus, const CubicPatch& minus, const Placement& place) {
  const int n = plus.n;
  const gp_Pnt p0 = place(plus.at(0, 0)), p1 = place(plus.at(n - 1, 0));
  const gp_Pnt m0 = place(minus.at(0, 0)), m1 = place(minus.at(n - 1, 0));
  BRepBuilderAPI_MakeWire wire;
  wire.Add(boundary_edge(plus, place));
  wire.Add(BRepBuilderAPI_MakeEdge(p1, m1).Edge());
  wire.Add(TopoDS::Edge(boundary_edge(minus, place).Reversed()));
  wire.Add(BRepBuilderAPI_MakeEdge(m0, p0).Edge());
  if (!wire.IsDone()) throw std::runtime_error("STEP: the wire of a cap face is not closed");
  BRepBuilderAPI_MakeFace face(wire.Wire(), true);
  if (!face.IsDone()) throw std::runtime_error("STEP: a cap face is not planar");
  return face.Face();
}

}  // namespace

WallBrep build_schwarzp_wall(const CubicPatch& plus, const CubicPatch& minus, const std::array<int, 3>& cells,
                             double cell_size) {
  WallBrep out;
  // The patches' shared curves are bitwise equal (cell_symmetry.h): sewing needs no slack beyond
  // rounding in the placement, far below any tolerance asked for.
  out.sewing_tolerance = 1e-9 * cell_size * std::max({cells[0], cells[1], cells[2]});
  BRepBuilderAPI_Sewing sewing(out.sewing_tolerance);
  for (int i = 0; i < cells[0]; ++i)
    for (int j = 0; j < cells[1]; ++j)
      for (int k = 0; k < cells[2]; ++k)
        for (const CellImage& image : cell_images()) {
          const Placement place{&image, {i, j, k}, cell_size};
          sewing.Add(patch_face(plus, place));
          sewing.Add(patch_face(minus, place));
          out.bspline_faces += 2;
          out.control_points += long(plus.n) * plus.n + long(minus.n) * minus.n;
          // A cap where the image of z = 0 is a face of the block.
          const int axis = image.face_axis();
          const int index = std::array<int, 3>{i, j, k}[static_cast<size_t>(axis)] + image.face_side();
          if (index == 0 || index == cells[static_cast<size_t>(axis)]) {
            sewing.Add(cap_face(plus, minus, place));
            ++out.planar_faces;
          }
        }
  sewing.Perform();
  out.free_edges = sewing.NbFreeEdges();
  if (out.free_edges != 0)
    throw std::runtime_error(fmt::format("STEP: sewing left {} free edges: the shell is open", out.free_edges));
  const TopoDS_Shape sewn = sewing.SewedShape();
  TopExp_Explorer shells(sewn, TopAbs_SHELL);
  if (!shells.More()) throw std::runtime_error("STEP: sewing made no shell");
  BRepBuilderAPI_MakeSolid make_solid;
  int shell_count = 0;
  for (; shells.More(); shells.Next()) {
    make_solid.Add(TopoDS::Shell(shells.Current()));
    ++shell_count;
  }
  if (shell_count != 1) throw std::runtime_error(fmt::format("STEP: sewing made {} shells, not one", shell_count));
  TopoDS_Solid solid = make_solid.Solid();
  BRepLib::OrientClosedSolid(solid);
  // The caps of one neck are 8 coplanar quadrilaterals: one planar face each neck.
  ShapeUpgrade_UnifySameDomain unify(solid, true, true, false);
  unify.Build();
  out.solid = unify.Shape();
  out.planar_faces = 0;
  for (TopExp_Explorer f(out.solid, TopAbs_FACE); f.More(); f.Next()) {
    Handle(Geom_Surface) s = BRep_Tool::Surface(TopoDS::Face(f.Current()));
    if (s->DynamicType() != STANDARD_TYPE(Geom_BSplineSurface)) ++out.planar_faces;
  }
  return out;
}

ShapeCheck check_shape(const TopoDS_Shape& shape) {
  ShapeCheck c;
  c.valid = BRepCheck_Analyzer(shape).IsValid();
  c.closed = true;
  for (TopExp_Explorer e(shape, TopAbs_SOLID); e.More(); e.Next()) ++c.solids;
  for (TopExp_Explorer e(shape, TopAbs_SHELL); e.More(); e.Next()) {
    ++c.shells;
    if (!BRep_Tool::IsClosed(e.Current())) c.closed = false;
  }
  for (TopExp_Explorer e(shape, TopAbs_FACE); e.More(); e.Next()) ++c.faces;
  GProp_GProps props;
  BRepGProp::VolumeProperties(shape, props, 1e-7, true);
  c.volume = props.Mass();
  return c;
}

}  // namespace offsetgen::step
