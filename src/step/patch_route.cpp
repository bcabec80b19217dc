#include "step/patch_route.h"

#include "step/box_brep.h"
#include "step/box_patch.h"
#include "step/cell_frame.h"
#include "step/exact_walls.h"
#include "support/stopwatch.h"
#include "surfaces/input_error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <iterator>
#include <memory>
#include <thread>
#include <vector>

namespace offsetgen::step {
namespace {

struct Fit {
  CubicPatch patch;
  double error = 0;  // cell units
};

// The n x n patch fitted to g's (3n + 1)^2 samples, and its largest |exact(u, v) - patch(u, v)| over
// a check grid (the midpoints of a grid twice as fine as the samples, and the samples' own lines).
// That distance bounds the distance of the exact point to the face from above.
Fit fit_at(const PatchLayout& layout, const LevelFunction& g, int n) {
  const int m = 3 * n + 1;
  Fit fit;
  fit.patch = fit_patch(patch_points(layout, g, m), m, n);
  snap_boundary(layout, fit.patch);
  const int c = 2 * m;
  std::vector<std::array<double, 2>> uv;
  for (int i = 0; i <= c; ++i)
    for (int j = 0; j <= c; ++j) uv.push_back({(i + 0.5 * (i < c)) / c, (j + 0.5 * (j < c)) / c});
  const std::vector<Point> exact = patch_points(layout, g, uv);
  for (size_t k = 0; k < uv.size(); ++k) {
    const Point p = fit.patch.evaluate(uv[k][0], uv[k][1]);
    fit.error = std::max(fit.error, std::hypot(p[0] - exact[k][0], p[1] - exact[k][1], p[2] - exact[k][2]));
  }
  return fit;
}

// The smallest patch within `target` (cell units), or the largest allowed.
Fit fit_sheet(const PatchLayout& layout, const LevelFunction& g, double target, int max_side) {
  Fit best;
  for (int n : kPatchSides) {
    if (n > max_side) break;
    best = fit_at(layout, g, n);
    if (best.error <= target) break;
  }
  return best;
}

// g seen from a patch's image: q -> g(map(q)).
LevelFunction through(const LevelFunction& g, const Isometry& map) {
  return [&g, map](size_t n, const double* x, const double* y, const double* z, double* out) {
    std::vector<double> mx(n), my(n), mz(n);
    for (size_t i = 0; i < n; ++i) {
      const Point q = map.apply({x[i], y[i], z[i]});
      mx[i] = q[0];
      my[i] = q[1];
      mz[i] = q[2];
    }
    g(n, mx.data(), my.data(), mz.data(), out);
  };
}

// The patches of both sheets: one each for a uniform wall (its images are copies), one per image of
// the region for a graded wall (the thickness breaks the symmetry; each image is fitted where it lies,
// on every core). All share one control-point count, so neighbours fitted from the same boundary
// samples share their boundary curve: the count that fits the patch's own image within the target,
// raised for all until every image is within it (or the request's limit is reached).
struct SheetPatches {
  std::vector<CubicPatch> plus, minus;
  int n = 0;
  double error = 0;  // cell units
};

SheetPatches fit_sheets(const PatchLayout& layout, const wall::WallField& field, const CellFrame& frame, bool graded,
                        const std::array<int, 3>& cells, double target, int max_side) {
  std::vector<Isometry> maps{Isometry{}};
  if (graded) {
    maps.clear();
    for (const PatchImage& image : region_images(layout, cells)) maps.push_back(image.map);
  }
  int n = 0;
  {
    wall::WallField::Worker worker(field);
    for (double side : {1.0, -1.0})
      n = std::max(n, fit_sheet(layout, offset_sheet(field, worker, frame, side, &cells), target, max_side).patch.n);
  }
  SheetPatches out;
  std::vector<Fit> plus(maps.size()), minus(maps.size());
  for (;;) {
    const unsigned threads = graded ? std::max(1u, std::thread::hardware_concurrency()) : 1u;
    std::vector<std::exception_ptr> failed(threads);
    auto work = [&](unsigned t) {
      try {
        wall::WallField::Worker worker(field);
        const LevelFunction p = offset_sheet(field, worker, frame, 1, &cells),
                            m = offset_sheet(field, worker, frame, -1, &cells);
        for (size_t i = t; i < maps.size(); i += threads) {
          plus[i] = fit_at(layout, through(p, maps[i]), n);
          minus[i] = fit_at(layout, through(m, maps[i]), n);
        }
      } catch (...) {
        failed[t] = std::current_exception();
      }
    };
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < threads; ++t) pool.emplace_back(work, t);
    work(0);
    for (std::thread& thread : pool) thread.join();
    for (const std::exception_ptr& e : failed)
      if (e) std::rethrow_exception(e);
    out.error = 0;
    for (size_t i = 0; i < maps.size(); ++i) out.error = std::max({out.error, plus[i].error, minus[i].error});
    const int* next = std::upper_bound(std::begin(kPatchSides), std::end(kPatchSides), n);
    if (out.error <= target || next == std::end(kPatchSides) || *next > max_side) break;
    n = *next;
  }
  out.n = n;
  for (size_t i = 0; i < maps.size(); ++i) {
    out.plus.push_back(std::move(plus[i].patch));
    out.minus.push_back(std::move(minus[i].patch));
  }
  return out;
}

// The gradient of phi(p, +t/2) at the middle of a plus patch (central differences): out of the wall.
Point outward(const wall::WallField& field, wall::WallField::Worker& worker, const CellFrame& frame,
              const CubicPatch& patch) {
  const LevelFunction g = offset_sheet(field, worker, frame, 1);
  const Point p = patch.evaluate(0.5, 0.5);
  constexpr double kStep = 1e-6;
  Point gradient{};
  for (size_t a = 0; a < 3; ++a) {
    Point lo = p, hi = p;
    lo[a] -= kStep;
    hi[a] += kStep;
    double values[2];
    const double x[2] = {lo[0], hi[0]}, y[2] = {lo[1], hi[1]}, z[2] = {lo[2], hi[2]};
    g(2, x, y, z, values);
    gradient[a] = values[1] - values[0];
  }
  return gradient;
}

// The symmetry route: one patch per sheet (or per image, graded), copied over the region.
WallBrep symmetry_wall(const PatchLayout& layout, const wall::WallField& field, wall::WallField::Worker& worker,
                       const StepRequest& r, double target, const InsideWall& inside_wall, StepSummary& s) {
  s.route = Route::Symmetry;
  auto t0 = Clock::now();
  const CellFrame frame = cell_frame(r);  // a cube cell: symmetry patches need the cube's mirror planes
  const SheetPatches patches = fit_sheets(layout, field, frame, s.graded, r.cells, target, r.max_control_points);
  s.patch_control_points = patches.n;
  s.fit_error = patches.error * frame.largest_mm();
  // A graded sheet is not perpendicular to the mirror planes: the jump is measured for uniform walls.
  if (!s.graded)
    for (const auto* sheet : {&patches.plus, &patches.minus})
      for (const CubicPatch& patch : *sheet)
        s.normal_jump = std::max(s.normal_jump, normal_jump(layout, patch, 200) * 180 / M_PI);
  s.seconds_fit = seconds_since(t0);
  t0 = Clock::now();
  WallBrep brep = build_wall(layout, patches.plus, patches.minus, outward(field, worker, frame, patches.plus.front()),
                             r.cells, frame.largest_mm(), inside_wall);
  s.seconds_build = seconds_since(t0);
  return brep;
}

// The box route (box_patch.h): quarter-cell boxes, each sheet's pieces in them fitted on their own;
// where a piece is no graph (it turns too far within a box) or a sheet touches a box's face, boxes
// half as large, down to 1/kFinestBoxes cell.
constexpr int kBoxesPerCell = 4, kFinestBoxes = 16;
BoxPartition partition_boxes(const std::array<LevelFunction, 2>& sheets,
                             const std::vector<std::array<LevelFunction, 2>>& more, const InsideWall& inside_wall,
                             const StepRequest& r, double target) {
  for (int k = kBoxesPerCell;; k *= 2) {
    try {
      return partition_wall(sheets, inside_wall, r.cells, k, target, r.max_control_points, more);
    } catch (const InputError& e) {
      if (k >= kFinestBoxes)
        throw InputError(fmt::format("STEP export cannot cut this wall into boxes down to 1/{} cell: {}", k, e.what()));
    }
  }
}

WallBrep box_wall(const wall::WallField& field, wall::WallField::Worker& worker, const StepRequest& r, double target,
                  const InsideWall& inside_wall, StepSummary& s) {
  s.route = Route::Box;
  auto t0 = Clock::now();
  const CellFrame frame = cell_frame(r);
  const std::array<LevelFunction, 2> sheets{offset_sheet(field, worker, frame, 1, &r.cells),
                                            offset_sheet(field, worker, frame, -1, &r.cells)};
  // The patches are fitted on every core, each thread with its own Worker.
  const unsigned threads = std::max(1u, std::thread::hardware_concurrency());
  std::vector<std::unique_ptr<wall::WallField::Worker>> workers;
  std::vector<std::array<LevelFunction, 2>> more;
  for (unsigned t = 1; t < threads; ++t) {
    workers.push_back(std::make_unique<wall::WallField::Worker>(field));
    more.push_back({offset_sheet(field, *workers.back(), frame, 1, &r.cells),
                    offset_sheet(field, *workers.back(), frame, -1, &r.cells)});
  }
  const BoxPartition partition = partition_boxes(sheets, more, inside_wall, r, target);
  s.boxes_per_cell = partition.boxes_per_cell;
  s.patch_control_points = partition.largest_side;
  s.fit_error = partition.fit_error * frame.largest_mm();  // at most: a cell unit is at most that many mm
  s.seconds_fit = seconds_since(t0);
  t0 = Clock::now();
  WallBrep brep = build_box_wall(partition, frame.mm);
  s.seconds_build = seconds_since(t0);
  return brep;
}

}  // namespace

const PatchLayout* choose_layout(const StepRequest& r) {
  const std::string& surface = r.wall.generation.surface;
  // A box cell keeps the mirror planes normal to the axes but not the diagonal ones the symmetry
  // patches are cut along (x = y, ...): its wall takes box patches, which need no symmetry.
  const bool box_cell = cell_frame(r).distorted();
  switch (r.patches) {
    case Patches::Box:
      return nullptr;
    case Patches::Symmetry: {
      if (box_cell)
        throw InputError(
            "--patches symmetry needs a cube cell: the symmetry patches are copied across the cube's diagonal "
            "mirror planes, which a box cell (--cell-size X,Y,Z of unequal sides) does not have; use --patches "
            "box or auto");
      const PatchLayout* layout = find_patch_layout(surface);
      if (layout == nullptr)
        throw InputError(
            fmt::format("--patches symmetry: '{}' has no mirror planes to cut it into symmetry patches "
                        "(they cover {}); use --patches box or auto",
                        surface, patch_layout_surfaces()));
      return layout;
    }
    case Patches::Auto:
      if (box_cell) return nullptr;
      break;
  }
  const PatchLayout* layout = find_patch_layout(surface);
  return layout != nullptr && layout->auto_prefers_box_patches ? nullptr : layout;
}

WallBrep fit_and_build_wall(const PatchLayout* layout, const wall::WallField& field, wall::WallField::Worker& worker,
                            const StepRequest& r, const InsideWall& inside_wall, StepSummary& s) {
  // Half of the tolerance for the fit, the rest is margin for what the check grid does not see; in cell
  // units, of which one is at most the cell's longest side in mm.
  const double target = 0.5 * r.tolerance / cell_frame(r).largest_mm();
  return layout != nullptr ? symmetry_wall(*layout, field, worker, r, target, inside_wall, s)
                           : box_wall(field, worker, r, target, inside_wall, s);
}

}  // namespace offsetgen::step
