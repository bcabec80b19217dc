// measure_deviation against faces whose distances are known: a curved bicubic face (a quarter of a
// cylinder's side, to the accuracy of its control net) and points above it, beside it and past its
// corner, where the nearest point of the face is inside, on an edge or at a corner.
#include "step/deviation.h"

#include <gtest/gtest.h>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRep_Tool.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Precision.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopoDS_Face.hxx>

#include <cmath>
#include <vector>

namespace offsetgen::step {
namespace {

// The bicubic Bezier patch (u, v) -> (x(u), v, z(u)) over [0, 1]^2 whose control points in u are those of
// a unit-circle quadrant's usual cubic (k = 0.5523); along v it is a straight extrusion of length 1.
TopoDS_Face quarter_cylinder() {
  constexpr double k = 0.5522847498;
  const double xs[4] = {1, 1, k, 0}, zs[4] = {0, k, 1, 1};
  TColgp_Array2OfPnt poles(1, 4, 1, 4);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) poles(i + 1, j + 1) = gp_Pnt(xs[i], j / 3.0, zs[i]);
  TColStd_Array1OfReal knots(1, 2);
  knots(1) = 0;
  knots(2) = 1;
  TColStd_Array1OfInteger mults(1, 2);
  mults(1) = mults(2) = 4;
  Handle(Geom_BSplineSurface) surface = new Geom_BSplineSurface(poles, knots, knots, mults, mults, 3, 3);
  return BRepBuilderAPI_MakeFace(surface, Precision::Confusion()).Face();
}

// Distances in mm with cell_size 1: the points are given in the face's own units.
double deviation_of(const Point& p) { return measure_deviation(quarter_cylinder(), {p}, {1, 1, 1}, 10.0).max; }

TEST(StepDeviation, PointAboveTheFaceIsItsRadialDistanceAway) {
  // The cubic quadrant stays within 3e-4 of the unit circle, so radius r is r - 1 away to that.
  for (double r : {1.2, 1.5, 0.7}) {
    const double a = 0.6;  // radians, inside the quadrant
    EXPECT_NEAR(deviation_of({r * std::cos(a), 0.4, r * std::sin(a)}), std::abs(r - 1), 4e-4) << r;
  }
}

TEST(StepDeviation, PointBesideAnEdgeMeasuresToTheEdge) {
  // Past the face's end at v = 1 (y = 1): the nearest point is on that edge, 0.5 beyond it.
  const double a = 0.9;
  EXPECT_NEAR(deviation_of({std::cos(a), 1.5, std::sin(a)}), 0.5, 4e-4);
}

TEST(StepDeviation, PointPastACornerMeasuresToTheCorner) {
  // The corner (1, 0, 0): the point is 0.3 below it along z and 0.4 before it along y.
  EXPECT_NEAR(deviation_of({1, -0.4, -0.3}), 0.5, 1e-9);
}

TEST(StepDeviation, PointOnTheFaceIsAtRoundingDistance) {
  const gp_Pnt on = BRep_Tool::Surface(quarter_cylinder())->Value(0.37, 0.81);
  EXPECT_LT(deviation_of({on.X(), on.Y(), on.Z()}), 1e-12);
}

TEST(StepDeviation, PointWithNoFaceWithinReachCountsAsReach) {
  const Deviation d = measure_deviation(quarter_cylinder(), {Point{5, 5, 5}}, {1, 1, 1}, 0.25);
  EXPECT_EQ(d.max, 0.25);
  EXPECT_EQ(d.points, 1);
}

}  // namespace
}  // namespace offsetgen::step
