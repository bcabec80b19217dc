#include "step/box_brep.h"

#include <BOPAlgo_ShellSplitter.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepLib.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <GeomAPI_Interpolate.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <ShapeUpgrade_UnifySameDomain.hxx>
#include <TColgp_Array1OfPnt2d.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TColgp_HArray1OfPnt.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Solid.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Ax3.hxx>
#include <gp_Pln.hxx>

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <stdexcept>
#include <utility>
#include <vector>

namespace offsetgen::step {
namespace {

class Assembly {
 public:
  Assembly(const BoxPartition& p, const Point& mm) : p_(p), mm_(mm), largest_(std::max({mm[0], mm[1], mm[2]})) {}

  WallBrep build() {
    vertices_.resize(p_.vertices.size());
    for (size_t i = 0; i < p_.vertices.size(); ++i) builder_.MakeVertex(vertices_[i], pnt(p_.vertices[i]), kTolerance);
    for (const BoxCurve& c : p_.curves) add_curve(c);
    TopoDS_Compound faces;
    builder_.MakeCompound(faces);
    std::vector<TopoDS_Face> all;
    WallBrep out;
    for (const BoxPatch& patch : p_.patches) {
      all.push_back(patch_face(patch));
      ++out.bspline_faces;
      out.control_points += long(patch.patch.n) * patch.patch.n;
    }
    for (const BoxCap& cap : p_.caps) {
      all.push_back(cap_face(cap));
      ++out.planar_faces;
    }
    for (const TopoDS_Face& f : all) builder_.Add(faces, f);
    // The parameter curves are the 3D curves' shadows on the patches: the edges' tolerances become the
    // largest distance between the two (the patches' fit error, at most).
    BRepLib::SameParameter(faces, 1e-7 * largest_, false);
    BOPAlgo_ShellSplitter shells;
    for (const TopoDS_Face& f : all) shells.AddStartElement(f);
    shells.Perform();
    TopoDS_Compound compound;
    builder_.MakeCompound(compound);
    TopoDS_Shape last;
    out.solids = 0;
    for (TopTools_ListOfShape::Iterator it(shells.Shells()); it.More(); it.Next(), ++out.solids) {
      if (!BRep_Tool::IsClosed(it.Value()))
        throw std::runtime_error("STEP: the box patches left a shell open (an edge with one face)");
      TopoDS_Solid solid;
      builder_.MakeSolid(solid);
      builder_.Add(solid, it.Value());
      builder_.Add(compound, solid);
      last = solid;
    }
    if (out.solids == 0) throw std::runtime_error("STEP: the box patches made no closed shell");
    out.solid = out.solids == 1 ? last : TopoDS_Shape(compound);
    // A cap is one face per box face; the caps of one region of a block face merge into one, as a
    // CAD user selects it (the 2x2x2 gyroid: 384 planar faces become 54; reading back is no slower).
    ShapeUpgrade_UnifySameDomain unify(out.solid, true, true, false);
    unify.Build();
    out.solid = unify.Shape();
    out.planar_faces = -out.bspline_faces;
    for (TopExp_Explorer f(out.solid, TopAbs_FACE); f.More(); f.Next()) ++out.planar_faces;
    return out;
  }

 private:
  static constexpr double kTolerance = 1e-7;

  // Cell units to mm, along each axis by its side: an affine map, so a B-spline's control points
  // mapped make the mapped curve or surface.
  gp_Pnt pnt(const Point& q) const { return {q[0] * mm_[0], q[1] * mm_[1], q[2] * mm_[2]}; }

  // The curve through its points (they lie on the sheet, evenly spaced), as an edge between its
  // two vertices.
  void add_curve(const BoxCurve& c) {
    Handle(TColgp_HArray1OfPnt) points = new TColgp_HArray1OfPnt(1, static_cast<int>(c.points.size()));
    for (size_t i = 0; i < c.points.size(); ++i) points->SetValue(static_cast<int>(i) + 1, pnt(c.points[i]));
    GeomAPI_Interpolate interpolate(points, false, 1e-12 * largest_);
    interpolate.Perform();
    if (!interpolate.IsDone())
      throw std::runtime_error("STEP: a curve where a sheet crosses a box's face cannot be interpolated");
    Handle(Geom_BSplineCurve) curve = interpolate.Curve();
    TopoDS_Edge edge;
    builder_.MakeEdge(edge, curve, kTolerance);
    builder_.Add(edge, vertices_[static_cast<size_t>(c.from)].Oriented(TopAbs_FORWARD));
    builder_.Add(edge, vertices_[static_cast<size_t>(c.to)].Oriented(TopAbs_REVERSED));
    builder_.Range(edge, curve->FirstParameter(), curve->LastParameter());
    builder_.SameParameter(edge, false);
    curves_.push_back(curve);
    edges_.push_back(edge);
  }

  // The straight segment between two vertices on a box's edge, one edge however many caps use it.
  TopoDS_Edge segment(int a, int b) {
    const std::pair<int, int> key{std::min(a, b), std::max(a, b)};
    const auto it = segments_.find(key);
    if (it != segments_.end()) return it->second;
    BRepBuilderAPI_MakeEdge make(vertices_[static_cast<size_t>(key.first)], vertices_[static_cast<size_t>(key.second)]);
    if (!make.IsDone()) throw std::runtime_error("STEP: a segment of a box's edge cannot be built");
    return segments_[key] = make.Edge();
  }

  TopoDS_Edge loop_edge(const LoopEdge& e) {
    if (e.curve >= 0) {
      const TopoDS_Edge& edge = edges_[static_cast<size_t>(e.curve)];
      return TopoDS::Edge(e.forward ? TopoDS_Shape(edge) : edge.Reversed());
    }
    const TopoDS_Edge edge = segment(e.from, e.to);
    return TopoDS::Edge(e.from < e.to ? TopoDS_Shape(edge) : edge.Reversed());
  }

  TopoDS_Face patch_face(const BoxPatch& patch) {
    const int n = patch.patch.n;
    TColgp_Array2OfPnt poles(1, n, 1, n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) poles.SetValue(i + 1, j + 1, pnt(patch.patch.at(i, j)));
    TColStd_Array1OfReal knots(1, 2);
    TColStd_Array1OfInteger mults(1, 2);
    knots_of(n, knots, mults);
    Handle(Geom_BSplineSurface) surface = new Geom_BSplineSurface(poles, knots, knots, mults, mults, 3, 3);
    TopoDS_Face face;
    builder_.MakeFace(face, surface, kTolerance);
    TopoDS_Wire wire;
    builder_.MakeWire(wire);
    for (const LoopEdge& e : patch.loop) {
      // The parameter curve: the 3D curve's control points in the patch's parameters.
      const Handle(Geom_BSplineCurve)& curve = curves_[static_cast<size_t>(e.curve)];
      TColgp_Array1OfPnt2d poles2d(1, curve->NbPoles());
      for (int k = 1; k <= curve->NbPoles(); ++k) {
        const gp_Pnt q = curve->Pole(k);
        const auto ab = patch.parameters({q.X() / mm_[0], q.Y() / mm_[1], q.Z() / mm_[2]});
        poles2d.SetValue(k, gp_Pnt2d(ab[0], ab[1]));
      }
      Handle(Geom2d_BSplineCurve) pcurve =
          new Geom2d_BSplineCurve(poles2d, curve->Knots(), curve->Multiplicities(), curve->Degree());
      builder_.UpdateEdge(edges_[static_cast<size_t>(e.curve)], pcurve, face, kTolerance);
      builder_.Add(wire, loop_edge(e));
    }
    wire.Closed(true);
    builder_.Add(face, wire);
    return face;
  }

  TopoDS_Face cap_face(const BoxCap& cap) {
    gp_Dir normal(cap.axis == 0 ? cap.outward : 0, cap.axis == 1 ? cap.outward : 0, cap.axis == 2 ? cap.outward : 0);
    Point origin{};
    origin[static_cast<size_t>(cap.axis)] = cap.offset;
    TopoDS_Wire wire;
    builder_.MakeWire(wire);
    for (const LoopEdge& e : cap.loop) builder_.Add(wire, loop_edge(e));
    wire.Closed(true);
    BRepBuilderAPI_MakeFace make(gp_Pln(pnt(origin), normal), wire, true);
    if (!make.IsDone()) throw std::runtime_error("STEP: a cap on the block's face cannot be built");
    return make.Face();
  }

  const BoxPartition& p_;
  Point mm_;
  double largest_;
  BRep_Builder builder_;
  std::vector<TopoDS_Vertex> vertices_;
  std::vector<Handle(Geom_BSplineCurve)> curves_;
  std::vector<TopoDS_Edge> edges_;
  std::map<std::pair<int, int>, TopoDS_Edge> segments_;
};

}  // namespace

WallBrep build_box_wall(const BoxPartition& partition, const Point& mm) { return Assembly(partition, mm).build(); }

}  // namespace offsetgen::step
