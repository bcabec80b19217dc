#include "step/wall_brep.h"

#include <BOPAlgo_Builder.hxx>
#include <BOPAlgo_ShellSplitter.hxx>
#include <BOPTools_AlgoTools.hxx>
#include <BOPTools_AlgoTools3D.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeSolid.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepGProp.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <GProp_GProps.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <IntTools_Context.hxx>
#include <ShapeUpgrade_UnifySameDomain.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Solid.hxx>
#include <gp_Pnt2d.hxx>
#include <gp_Vec.hxx>

#include <fmt/format.h>

#include <algorithm>
#include <functional>
#include <future>
#include <stdexcept>
#include <vector>

namespace offsetgen::step {
namespace {

struct Placement {
  const Isometry* map;
  double cell_size;
  gp_Pnt operator()(const Point& p) const {
    const Point q = map->apply(p);
    return gp_Pnt(q[0] * cell_size, q[1] * cell_size, q[2] * cell_size);
  }
};

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

// The control points of side k of a patch (u = 0, u = 1, v = 0, v = 1), in order.
std::vector<Point> side_curve(const CubicPatch& patch, size_t k) {
  const int n = patch.n;
  std::vector<Point> out;
  for (int t = 0; t < n; ++t) {
    if (k == 0) out.push_back(patch.at(0, t));
    if (k == 1) out.push_back(patch.at(n - 1, t));
    if (k == 2) out.push_back(patch.at(t, 0));
    if (k == 3) out.push_back(patch.at(t, n - 1));
  }
  return out;
}

TopoDS_Edge curve_edge(const std::vector<Point>& control, const Placement& place) {
  const int n = static_cast<int>(control.size());
  TColgp_Array1OfPnt poles(1, n);
  for (int i = 0; i < n; ++i) poles.SetValue(i + 1, place(control[static_cast<size_t>(i)]));
  TColStd_Array1OfReal knots(1, 2);
  TColStd_Array1OfInteger mults(1, 2);
  knots_of(n, knots, mults);
  Handle(Geom_BSplineCurve) curve = new Geom_BSplineCurve(poles, knots, mults, 3);
  return BRepBuilderAPI_MakeEdge(curve).Edge();
}

// The cap between the two sheets' side k on a face of the region: a planar quadrilateral (the two
// boundary curves and two segments on the tetrahedron's edges at their ends).
TopoDS_Face cap_face(const CubicPatch& plus, const CubicPatch& minus, size_t k, const Placement& place) {
  const std::vector<Point> p = side_curve(plus, k), m = side_curve(minus, k);
  const gp_Pnt p0 = place(p.front()), p1 = place(p.back()), m0 = place(m.front()), m1 = place(m.back());
  BRepBuilderAPI_MakeWire wire;
  wire.Add(curve_edge(p, place));
  wire.Add(BRepBuilderAPI_MakeEdge(p1, m1).Edge());
  wire.Add(TopoDS::Edge(curve_edge(m, place).Reversed()));
  wire.Add(BRepBuilderAPI_MakeEdge(m0, p0).Edge());
  if (!wire.IsDone()) throw std::runtime_error("STEP: the wire of a cap face is not closed");
  BRepBuilderAPI_MakeFace face(wire.Wire(), true);
  if (!face.IsDone()) throw std::runtime_error("STEP: a cap face is not planar");
  return face.Face();
}

// Where a face lies against the block [0, size]: inside it, outside it, or across one of its faces.
enum class Side { Inside, Outside, Across };
Side side_of(const TopoDS_Face& face, const std::array<double, 3>& size, double margin) {
  Bnd_Box box;
  BRepBndLib::Add(face, box);
  double lo[3], hi[3];
  box.Get(lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]);
  bool inside = true;
  for (size_t a = 0; a < 3; ++a) {
    if (hi[a] < -margin || lo[a] > size[a] + margin) return Side::Outside;
    inside = inside && lo[a] > margin && hi[a] < size[a] - margin;
  }
  return inside ? Side::Inside : Side::Across;
}

// The wall solid cut to the block: the faces inside the block are kept as they are, those outside
// dropped, and only the faces across the box's faces are split by them (OpenCASCADE's general fuse
// of those faces with the box: about half of diamond's, whose tetrahedra are long; faster than a
// boolean common of the whole solid). Of the pieces, those of the wall's
// faces inside the block and those of the box's faces inside the exact wall (`inside_wall`, at a
// point inside each piece) close the solids again.
TopoDS_Shape cut_to_block(const TopoDS_Shape& solid, const std::array<double, 3>& size, double cell_size,
                          const std::function<bool(const Point&)>& inside_wall, int& solids) {
  const double margin = 1e-7 * cell_size;
  std::vector<TopoDS_Face> kept;
  TopoDS_Compound across;
  BRep_Builder builder;
  builder.MakeCompound(across);
  std::vector<TopoDS_Face> split;
  for (TopExp_Explorer e(solid, TopAbs_FACE); e.More(); e.Next()) {
    const TopoDS_Face& face = TopoDS::Face(e.Current());
    switch (side_of(face, size, margin)) {
      case Side::Inside:
        kept.push_back(face);
        break;
      case Side::Across:
        builder.Add(across, face);
        split.push_back(face);
        break;
      case Side::Outside:
        break;
    }
  }
  const TopoDS_Shape box = BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), size[0], size[1], size[2]).Shape();
  BOPAlgo_Builder fuse;
  fuse.AddArgument(across);
  fuse.AddArgument(box);
  fuse.SetRunParallel(true);
  fuse.SetUseOBB(true);
  fuse.Perform();
  if (fuse.HasErrors()) throw std::runtime_error("STEP: splitting the wall's faces by the block's box failed");
  const Handle(IntTools_Context) context = fuse.Context();
  // The pieces of `face`, oriented as it is; `keep` says which belong to the cut solid.
  auto add_pieces = [&](const TopoDS_Face& face, const std::function<bool(const gp_Pnt&)>& keep) {
    const TopTools_ListOfShape& images = fuse.Modified(face);
    TopTools_ListOfShape pieces;
    if (images.IsEmpty()) {
      pieces.Append(face);
    } else {
      pieces = images;
    }
    for (TopTools_ListOfShape::Iterator it(pieces); it.More(); it.Next()) {
      TopoDS_Face piece = TopoDS::Face(it.Value());
      gp_Pnt point;
      gp_Pnt2d uv;
      if (BOPTools_AlgoTools3D::PointInFace(piece, point, uv, context) != 0)
        throw std::runtime_error("STEP: no point inside a piece of a face cut by the block's box");
      if (!keep(point)) continue;
      if (!images.IsEmpty() && BOPTools_AlgoTools::IsSplitToReverse(piece, face, context)) piece.Reverse();
      kept.push_back(piece);
    }
  };
  const double slack = 1e-6 * cell_size;
  for (const TopoDS_Face& face : split)
    add_pieces(face, [&](const gp_Pnt& p) {
      return p.X() > -slack && p.Y() > -slack && p.Z() > -slack && p.X() < size[0] + slack && p.Y() < size[1] + slack &&
             p.Z() < size[2] + slack;
    });
  for (TopExp_Explorer e(box, TopAbs_FACE); e.More(); e.Next())
    add_pieces(TopoDS::Face(e.Current()), [&](const gp_Pnt& p) {
      return inside_wall({p.X() / cell_size, p.Y() / cell_size, p.Z() / cell_size});
    });
  BOPAlgo_ShellSplitter shells;
  for (const TopoDS_Face& face : kept) shells.AddStartElement(face);
  shells.Perform();
  TopoDS_Compound compound;
  builder.MakeCompound(compound);
  TopoDS_Shape last;
  solids = 0;
  for (TopTools_ListOfShape::Iterator it(shells.Shells()); it.More(); it.Next(), ++solids) {
    TopoDS_Solid piece;
    builder.MakeSolid(piece);
    builder.Add(piece, it.Value());
    builder.Add(compound, piece);
    last = piece;
  }
  if (solids == 0) throw std::runtime_error("STEP: cutting the wall to the block left no solid");
  return solids == 1 ? last : TopoDS_Shape(compound);
}

}  // namespace

void knots_of(int n, TColStd_Array1OfReal& knots, TColStd_Array1OfInteger& mults) {
  const CubicKnots k(n);
  knots.Resize(1, static_cast<int>(k.distinct.size()), false);
  mults.Resize(1, static_cast<int>(k.distinct.size()), false);
  for (size_t i = 0; i < k.distinct.size(); ++i) {
    knots.SetValue(static_cast<int>(i) + 1, k.distinct[i]);
    mults.SetValue(static_cast<int>(i) + 1, k.multiplicities[i]);
  }
}

WallBrep build_wall(const PatchLayout& layout, const std::vector<CubicPatch>& plus,
                    const std::vector<CubicPatch>& minus, const Point& plus_outward, const std::array<int, 3>& cells,
                    double cell_size, const std::function<bool(const Point&)>& inside_wall) {
  WallBrep out;
  // The patches' shared curves are equal to the last bit or within a few units of it
  // (symmetry_patch.h): sewing needs no slack beyond rounding, far below any tolerance asked for.
  out.sewing_tolerance = 1e-9 * cell_size * std::max({cells[0], cells[1], cells[2]});
  BRepBuilderAPI_Sewing sewing(out.sewing_tolerance);
  const std::vector<PatchImage> images = region_images(layout, cells);
  const bool each = plus.size() > 1;
  if (plus.size() != minus.size() || (each && plus.size() != images.size()))
    throw std::logic_error("build_wall: one patch per sheet, or one per image");
  TopoDS_Face first;  // the plus sheet's face in the patch's own tetrahedron (images[0] is the identity)
  for (size_t i = 0; i < images.size(); ++i) {
    const PatchImage& image = images[i];
    const CubicPatch &p = plus[each ? i : 0], &m = minus[each ? i : 0];
    const Placement place{&image.map, cell_size};
    const TopoDS_Face face = patch_face(p, place);
    if (i == 0) first = face;
    sewing.Add(face);
    sewing.Add(patch_face(m, place));
    for (size_t k = 0; k < 4; ++k)
      if (image.cap[k]) sewing.Add(cap_face(p, m, k, place));
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
  // Sewing orients the faces consistently; the solid is the wall if the first face's normal points
  // away from it, along `plus_outward` (classifying a point against thousands of faces, as
  // BRepLib::OrientClosedSolid does, takes seconds).
  const TopoDS_Shape sewn_first = sewing.Modified(first);
  bool found = false;
  for (TopExp_Explorer e(solid, TopAbs_FACE); e.More() && !found; e.Next()) {
    if (!e.Current().IsSame(sewn_first)) continue;
    found = true;
    const TopoDS_Face& face = TopoDS::Face(e.Current());
    BRepAdaptor_Surface surface(face);
    gp_Pnt point;
    gp_Vec du, dv;
    surface.D1(0.5 * (surface.FirstUParameter() + surface.LastUParameter()),
               0.5 * (surface.FirstVParameter() + surface.LastVParameter()), point, du, dv);
    gp_Vec normal = du.Crossed(dv);
    if (face.Orientation() == TopAbs_REVERSED) normal.Reverse();
    if (normal.Dot(gp_Vec(plus_outward[0], plus_outward[1], plus_outward[2])) < 0) solid.Reverse();
  }
  if (!found) throw std::runtime_error("STEP: the first face is missing from the sewn shell");
  TopoDS_Shape shape = solid;
  if (!layout.region_is_block) {
    // The region's faces lie outside the block: the block's box cuts the wall to it.
    if (!inside_wall) throw std::logic_error("build_wall: a region larger than the block needs inside_wall");
    const std::array<double, 3> size{cells[0] * cell_size, cells[1] * cell_size, cells[2] * cell_size};
    shape = cut_to_block(solid, size, cell_size, inside_wall, out.solids);
  }
  // The caps of one neck are coplanar quadrilaterals: one planar face each.
  ShapeUpgrade_UnifySameDomain unify(shape, true, true, false);
  unify.Build();
  out.solid = unify.Shape();
  for (TopExp_Explorer f(out.solid, TopAbs_FACE); f.More(); f.Next()) {
    Handle(Geom_BSplineSurface) b =
        Handle(Geom_BSplineSurface)::DownCast(BRep_Tool::Surface(TopoDS::Face(f.Current())));
    if (b.IsNull()) {
      ++out.planar_faces;
      continue;
    }
    ++out.bspline_faces;
    out.control_points += long(b->NbUPoles()) * b->NbVPoles();
  }
  return out;
}

ShapeCheck check_shape(const TopoDS_Shape& shape) {
  // The volume is integrated on a second core while BRepCheck analyses: both only read the shape.
  std::future<double> volume = std::async(std::launch::async, [&shape] {
    GProp_GProps props;
    BRepGProp::VolumeProperties(shape, props, true);  // Gauss points per knot span: exact to rounding for bicubic faces
    return props.Mass();
  });
  ShapeCheck c;
  c.valid = BRepCheck_Analyzer(shape).IsValid();
  c.closed = true;
  for (TopExp_Explorer e(shape, TopAbs_SOLID); e.More(); e.Next()) ++c.solids;
  for (TopExp_Explorer e(shape, TopAbs_SHELL); e.More(); e.Next()) {
    ++c.shells;
    if (!BRep_Tool::IsClosed(e.Current())) c.closed = false;
  }
  for (TopExp_Explorer e(shape, TopAbs_FACE); e.More(); e.Next()) ++c.faces;
  c.volume = volume.get();
  return c;
}

}  // namespace offsetgen::step
