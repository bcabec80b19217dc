#include "step/step_export.h"

#include "density/surface_constants.h"
#include "emit/file_writer.h"
#include "numeric/volume_fraction.h"
#include "run/process.h"
#include "step/box_brep.h"
#include "step/box_patch.h"
#include "step/deviation.h"
#include "step/step_file.h"
#include "step/symmetry_patch.h"
#include "step/wall_brep.h"
#include "support/stopwatch.h"
#include "surfaces/input_error.h"

#include <fmt/format.h>
#include <BRep_Tool.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <exception>
#include <filesystem>
#include <fstream>
#include <functional>
#include <future>
#include <map>
#include <memory>
#include <sstream>
#include <thread>

namespace offsetgen::step {
namespace {

namespace fs = std::filesystem;

// Control points per patch side tried in turn, up to the request's limit.
// The jitter of the deviation's lines: fixed, so a run is repeatable.
constexpr uint64_t kSeed = 20261126;

constexpr int kSides[] = {4, 5, 6, 7, 8, 10, 12, 14, 16, 20, 24, 28, 32, 40, 48, 64};

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
  for (int n : kSides) {
    if (n > max_side) break;
    best = fit_at(layout, g, n);
    if (best.error <= target) break;
  }
  return best;
}

// One offset sheet, phi(p, side t(p) / 2) = 0 with side +1 or -1; t uniform or graded. With `block`,
// a graded t is taken at the nearest point of the block [0, cells]: diamond's patches reach beyond
// it (the box cuts them afterwards), where the expression may not be positive or may be nothing the
// user asked for; inside the block the sheet is unchanged.
LevelFunction offset_sheet(const wall::WallField& field, wall::WallField::Worker& worker, double side,
                           const std::array<int, 3>* block = nullptr) {
  return [&field, &worker, side, block](size_t n, const double* x, const double* y, const double* z, double* out) {
    std::vector<double> h(n);
    for (size_t i = 0; i < n; ++i) {
      Point p{x[i], y[i], z[i]};
      if (block != nullptr)
        for (size_t a = 0; a < 3; ++a) p[a] = std::clamp(p[a], 0.0, double((*block)[a]));
      h[i] = side * 0.5 * field.thickness_at(p[0], p[1], p[2], worker);
    }
    field.offsets(n, x, y, z, h.data(), out);
  };
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

SheetPatches fit_sheets(const PatchLayout& layout, const wall::WallField& field, bool graded,
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
      n = std::max(n, fit_sheet(layout, offset_sheet(field, worker, side, &cells), target, max_side).patch.n);
  }
  SheetPatches out;
  std::vector<Fit> plus(maps.size()), minus(maps.size());
  for (;;) {
    const unsigned threads = graded ? std::max(1u, std::thread::hardware_concurrency()) : 1u;
    std::vector<std::exception_ptr> failed(threads);
    auto work = [&](unsigned t) {
      try {
        wall::WallField::Worker worker(field);
        const LevelFunction p = offset_sheet(field, worker, 1, &cells), m = offset_sheet(field, worker, -1, &cells);
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
    const int* next = std::upper_bound(std::begin(kSides), std::end(kSides), n);
    if (out.error <= target || next == std::end(kSides) || *next > max_side) break;
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
Point outward(const wall::WallField& field, wall::WallField::Worker& worker, const CubicPatch& patch) {
  const LevelFunction g = offset_sheet(field, worker, 1);
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

// Checks what the exporter covers of the wall, and records its thickness.
void prepare_walls(const wall::WallField& field, wall::WallField::Worker& worker, const StepRequest& r,
                   StepSummary& s) {
  if (field.graded() && r.wall.thickness.empty())
    throw InputError(
        "STEP export takes a graded wall as --thickness EXPR (an expression of x, y, z); --density-field is refused");
  s.graded = field.graded();
  s.thickness = field.thickness_at(0, 0, 0, worker);
  s.thickness_range = field.thickness_range(r.cells);
  s.thickness_text = s.graded ? r.wall.thickness : fmt::format("{}", s.thickness);
  try {
    s.thickness_limit = density::surface_constants(field.generation().surface).thickness_limit();
  } catch (const InputError& e) {
    throw InputError(
        fmt::format("offsetgen step needs the surface's curvature limit, from its constants: {}", e.what()));
  }
  if (!(s.thickness_range[1] < s.thickness_limit))
    throw InputError(fmt::format(
        "--thickness {} is beyond the curvature limit of {}{}: t/2 must stay below the smallest radius of "
        "curvature, t < {:.6f} (cell units)",
        s.thickness_text, s.surface, s.graded ? fmt::format(" (it reaches {} in the block)", s.thickness_range[1]) : "",
        s.thickness_limit));
}

// The request, as the file's header carries it for `offsetgen check` (kMetadataTag, then JSON).
constexpr const char* kMetadataTag = "offsetgen-metadata ";

std::string request_metadata(const StepRequest& r, const StepSummary& s) {
  nlohmann::ordered_json j;
  const GenerationRequest& g = r.wall.generation;
  if (g.expression.empty()) {
    j["surface"] = g.surface;
  } else {  // the expression itself, so check can build the same walls again
    j["expr"] = g.expression;
    j["name"] = g.name;
    if (!g.params.empty()) j["params"] = g.params;
  }
  j["method"] = r.wall.generation.method;
  j["order"] = r.wall.generation.order;
  j["thickness"] = s.thickness_text;  // a uniform one as the shortest text that reads back as the same double
  j["cells"] = r.cells;
  j["cell_size"] = r.cell_size;
  j["tolerance"] = r.tolerance;
  j["solids"] = s.expected_solids;
  return kMetadataTag + j.dump();
}

// The request a file's header describes; InputError naming what is missing.
StepRequest request_from_description(const std::string& description, const std::string& path, int& solids) {
  const size_t at = description.find(kMetadataTag);
  if (at == std::string::npos)
    throw InputError(fmt::format(
        "{}: no offsetgen-metadata in its header (FILE_DESCRIPTION): check measures a STEP file of `offsetgen step` "
        "against the walls it was made from, and this one does not say which",
        path));
  StepRequest r;
  try {
    const auto j = nlohmann::json::parse(description.substr(at + std::string(kMetadataTag).size()));
    if (j.contains("expr")) {
      r.wall.generation.expression = j.at("expr").get<std::string>();
      r.wall.generation.name = j.at("name").get<std::string>();
      r.wall.generation.params = j.value("params", std::map<std::string, std::string>{});
    } else {
      r.wall.generation.surface = j.at("surface").get<std::string>();
    }
    r.wall.generation.method = j.at("method").get<std::string>();
    r.wall.generation.order = j.at("order").get<int>();
    r.wall.thickness = j.at("thickness").get<std::string>();
    r.cells = j.at("cells").get<std::array<int, 3>>();
    r.cell_size = j.at("cell_size").get<double>();
    r.tolerance = j.at("tolerance").get<double>();
    solids = j.value("solids", 1);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(fmt::format("{}: its offsetgen-metadata cannot be read: {}", path, e.what()));
  }
  if (!(r.tolerance > 0) || !(r.cell_size > 0) || r.cells[0] < 1 || r.cells[1] < 1 || r.cells[2] < 1 || solids < 1)
    throw InputError(fmt::format("{}: its offsetgen-metadata holds a block or tolerance out of range", path));
  return r;
}

// B-spline faces and their control points, counted on a shape.
void count_bspline_faces(const TopoDS_Shape& shape, StepSummary& s) {
  s.bspline_faces = 0;
  s.control_points = 0;
  for (TopExp_Explorer e(shape, TopAbs_FACE); e.More(); e.Next()) {
    const Handle(Geom_BSplineSurface) b =
        Handle(Geom_BSplineSurface)::DownCast(BRep_Tool::Surface(TopoDS::Face(e.Current())));
    if (b.IsNull()) continue;
    ++s.bspline_faces;
    s.control_points += long(b->NbUPoles()) * b->NbVPoles();
  }
}

// The exact wall's level at one point p[0..2] (cell units): negative inside (wall::WallField::walls).
double wall_at(const wall::WallField& field, wall::WallField::Worker& worker, const double* p) {
  double w = 0;
  field.walls(1, p, p + 1, p + 2, &w, worker);
  return w;
}

// The exact wall volume by column quadrature (check/volume_fraction.h): a uniform wall's volume
// fraction in one cell times the cells (the block is whole cells of a periodic wall); a graded wall's,
// cell by cell. It needs only the wall's functions, with a Worker of its own, so it runs on a thread of
// its own while OpenCASCADE writes and checks the solid (or, in check, reads it) on one core.
struct ExactVolume {
  double volume = 0, error = 0, seconds = 0;
};
ExactVolume exact_wall_volume(const wall::WallField& field, const StepRequest& r, std::array<double, 2> thickness,
                              bool graded) {
  const auto t0 = Clock::now();
  wall::WallField::Worker worker(field);
  numeric::VolumeFractionSetup v;
  v.g = [&field, &worker](const double* p) { return wall_at(field, worker, p); };
  v.field = [&field](const double* p) { return field.field(p[0], p[1], p[2]); };
  v.field_slope_bound = field.field_lipschitz();
  v.band = field.field_lipschitz() * 0.5 * thickness[1] * (1 + 1e-9);
  v.scan_step = thickness[0] / 4;
  const double cell = std::pow(r.cell_size, 3);
  std::vector<std::array<int, 3>> cells{{0, 0, 0}};
  if (graded) {
    v.periodic = false;
    cells.clear();
    for (int i = 0; i < r.cells[0]; ++i)
      for (int j = 0; j < r.cells[1]; ++j)
        for (int k = 0; k < r.cells[2]; ++k) cells.push_back({i, j, k});
  }
  const double copies = graded ? 1.0 : double(r.cells[0]) * r.cells[1] * r.cells[2];
  double variance = 0;
  ExactVolume out;
  for (const auto& at : cells) {
    v.origin = {double(at[0]), double(at[1]), double(at[2])};
    const numeric::VolumeFraction fraction = numeric::measure_volume_fraction(v, numeric::VolumeFractionOptions{});
    out.volume += fraction.value * cell * copies;
    variance += std::pow(fraction.standard_error * cell * copies, 2);
  }
  out.error = std::sqrt(variance);
  out.seconds = seconds_since(t0);
  return out;
}

std::future<ExactVolume> start_exact_wall_volume(const wall::WallField& field, const StepRequest& r,
                                                 const StepSummary& s) {
  return std::async(std::launch::async, exact_wall_volume, std::cref(field), std::cref(r), s.thickness_range, s.graded);
}

// The volume of a file that passes: within 0.1% of the exact wall volume (issue 28), beyond three
// standard errors of the quadrature.
constexpr double kVolumeTolerance = 1e-3;
bool volume_agrees(const StepSummary& s) {
  return std::abs(s.volume - s.exact_volume) <= kVolumeTolerance * s.exact_volume + 3 * s.exact_volume_error;
}

// Everything measured on a solid, by export (the solid it writes) and check (the file read back) alike:
// valid closed solids, as many as the wall has pieces in the block, the exact walls' deviation from its
// faces, its volume against the exact wall volume.
void measure_solid(const TopoDS_Shape& shape, const StepRequest& r, wall::WallField& field,
                   wall::WallField::Worker& worker, std::future<ExactVolume>& exact_volume, StepSummary& s) {
  auto t0 = Clock::now();
  const ShapeCheck c = check_shape(shape);
  s.seconds_check = seconds_since(t0);
  t0 = Clock::now();
  s.valid = c.valid;
  s.closed = c.closed && c.shells == c.solids;
  s.solids = c.solids;
  s.volume = c.volume;
  const long control_points = s.control_points;
  count_bspline_faces(shape, s);
  if (control_points > 0) s.control_points = control_points;  // export: the solid's own count
  s.control_points_per_cell = double(s.control_points) / (double(r.cells[0]) * r.cells[1] * r.cells[2]);
  s.planar_faces = c.faces - s.bspline_faces;

  // The exact wall points: lines along each axis, 12 per cell side, scanned at t/4 (the thinnest t).
  const LevelFunction plus = offset_sheet(field, worker, 1), minus = offset_sheet(field, worker, -1);
  const int steps = std::max(16, static_cast<int>(std::ceil(4 / s.thickness_range[0])));
  std::vector<Point> points = exact_surface_points(plus, r.cells, 12, steps, kSeed);
  const std::vector<Point> more = exact_surface_points(minus, r.cells, 12, steps, kSeed + 1);
  points.insert(points.end(), more.begin(), more.end());
  // Only faces within twice the tolerance of a point are tried: a point with none is beyond the tolerance.
  const Deviation d = measure_deviation(shape, points, r.cell_size, 2 * r.tolerance);
  s.max_deviation = d.max;
  s.mean_deviation = d.mean;
  s.deviation_points = d.points;
  s.worst_point = d.worst;
  s.seconds_deviation = seconds_since(t0);

  const ExactVolume exact = exact_volume.get();
  s.exact_volume = exact.volume;
  s.exact_volume_error = exact.error;
  s.seconds_volume = exact.seconds;

  if (!s.valid || !s.closed || s.solids != s.expected_solids)
    s.failure = fmt::format("the shape is not {} valid closed solid{} (valid {}, solids {}, closed {})",
                            s.expected_solids, s.expected_solids == 1 ? "" : "s", s.valid, s.solids, s.closed);
  else if (!(s.max_deviation <= r.tolerance))
    s.failure = fmt::format("the measured deviation {:.3g} mm exceeds --tolerance {} mm", s.max_deviation, r.tolerance);
  // The fit's small signed error adds up over the faces: it matters for thin walls (a 0.2 mm gyroid
  // wall at 0.01 mm is off by +0.086%, at 0.003 mm by -0.02%).
  else if (!volume_agrees(s))
    s.failure = fmt::format(
        "the solid's volume {:.6f} mm^3 differs from the exact wall's {:.6f} mm^3 by more than {}% (a smaller "
        "--tolerance brings the faces, and their volume, closer)",
        s.volume, s.exact_volume, 100 * kVolumeTolerance);
}

// The written text holds one MANIFOLD_SOLID_BREP per solid and one ADVANCED_FACE per face of the solid
// measured: the translation lost nothing. "" when it does, else what is missing.
size_t occurrences(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}
std::string file_holds_the_solid(const std::string& bytes, const TopoDS_Shape& solid) {
  size_t solids = 0, faces = 0;
  for (TopExp_Explorer e(solid, TopAbs_SOLID); e.More(); e.Next()) ++solids;
  for (TopExp_Explorer e(solid, TopAbs_FACE); e.More(); e.Next()) ++faces;
  const size_t written_solids = occurrences(bytes, "MANIFOLD_SOLID_BREP("),
               written_faces = occurrences(bytes, "ADVANCED_FACE(");
  if (written_solids == solids && written_faces == faces) return "";
  return fmt::format("the STEP file holds {} solids and {} faces of the solid's {} and {} (STEPControl_Writer)",
                     written_solids, written_faces, solids, faces);
}

using InsideWall = std::function<bool(const Point&)>;

// The symmetry route: one patch per sheet (or per image, graded), copied over the region.
WallBrep symmetry_wall(const PatchLayout& layout, const wall::WallField& field, wall::WallField::Worker& worker,
                       const StepRequest& r, double target, const InsideWall& inside_wall, StepSummary& s) {
  s.patches = "symmetry patch";
  auto t0 = Clock::now();
  const SheetPatches patches = fit_sheets(layout, field, s.graded, r.cells, target, r.max_control_points);
  s.patch_control_points = patches.n;
  s.fit_error = patches.error * r.cell_size;
  // A graded sheet is not perpendicular to the mirror planes: the jump is measured for uniform walls.
  if (!s.graded)
    for (const auto* sheet : {&patches.plus, &patches.minus})
      for (const CubicPatch& patch : *sheet)
        s.normal_jump = std::max(s.normal_jump, normal_jump(layout, patch, 200) * 180 / M_PI);
  s.seconds_fit = seconds_since(t0);
  t0 = Clock::now();
  WallBrep brep = build_wall(layout, patches.plus, patches.minus, outward(field, worker, patches.plus.front()), r.cells,
                             r.cell_size, inside_wall);
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
  auto t0 = Clock::now();
  const std::array<LevelFunction, 2> sheets{offset_sheet(field, worker, 1, &r.cells),
                                            offset_sheet(field, worker, -1, &r.cells)};
  // The patches are fitted on every core, each thread with its own Worker.
  const unsigned threads = std::max(1u, std::thread::hardware_concurrency());
  std::vector<std::unique_ptr<wall::WallField::Worker>> workers;
  std::vector<std::array<LevelFunction, 2>> more;
  for (unsigned t = 1; t < threads; ++t) {
    workers.push_back(std::make_unique<wall::WallField::Worker>(field));
    more.push_back(
        {offset_sheet(field, *workers.back(), 1, &r.cells), offset_sheet(field, *workers.back(), -1, &r.cells)});
  }
  const BoxPartition partition = partition_boxes(sheets, more, inside_wall, r, target);
  s.boxes_per_cell = partition.boxes_per_cell;
  s.patches = fmt::format("box patch (the largest; boxes of 1/{} cell)", partition.boxes_per_cell);
  s.patch_control_points = partition.largest_side;
  s.fit_error = partition.fit_error * r.cell_size;
  s.seconds_fit = seconds_since(t0);
  t0 = Clock::now();
  WallBrep brep = build_box_wall(partition, r.cell_size);
  s.seconds_build = seconds_since(t0);
  return brep;
}

// The catalog name, or an expression's name (its --name) for the summary.
std::string surface_words(const GenerationRequest& g) {
  return g.expression.empty() ? g.surface : fmt::format("{} (F = {})", g.name, g.expression);
}

std::string read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

StepSummary export_step(const StepRequest& r, const std::function<void(const std::string&)>& progress) {
  const auto start = Clock::now();
  const std::clock_t cpu_start = std::clock();
  auto say = [&](const std::string& what) {
    if (progress) progress(what);
  };
  // Cheap checks first.
  if (!(r.tolerance > 0) || !std::isfinite(r.tolerance))
    throw InputError(
        fmt::format("--tolerance {}: give the largest deviation allowed, a positive length in mm", r.tolerance));
  if (!(r.cell_size > 0) || !std::isfinite(r.cell_size))
    throw InputError(fmt::format("--cell-size {}: a cell is a positive length in mm", r.cell_size));
  if (r.output.empty()) throw InputError("no output file: use -o part.step");
  const std::string ext = fs::path(r.output).extension().string();
  if (ext != ".step" && ext != ".stp" && ext != ".STEP" && ext != ".STP")
    throw InputError(fmt::format("-o '{}': STEP files end in .step or .stp", r.output));
  // A surface with mirror planes gets its symmetry patches (diamond only when asked for them); the
  // others (the gyroid) box patches.
  const PatchLayout* layout = r.patches == "box" ? nullptr : find_patch_layout(r.wall.generation.surface);
  if (r.patches == "auto" && layout != nullptr && layout->auto_prefers_box_patches) layout = nullptr;
  if (r.patches == "symmetry" && layout == nullptr)
    throw InputError(
        fmt::format("--patches symmetry: '{}' has no mirror planes to cut it into symmetry patches "
                    "(they cover {}); use --patches box or auto",
                    r.wall.generation.surface, patch_layout_surfaces()));
  if (r.patches != "auto" && r.patches != "symmetry" && r.patches != "box")
    throw InputError(fmt::format("--patches {}: give auto, symmetry or box", r.patches));
  try {
    require_writable(r.output);  // an unwritable -o is the user's input, before the long work
  } catch (const std::runtime_error& e) {
    throw InputError(e.what());
  }

  StepSummary s;
  s.surface = surface_words(r.wall.generation);
  say("generating the wall's functions");
  wall::WallField field(r.wall);
  wall::WallField::Worker worker(field);
  prepare_walls(field, worker, r, s);
  say("compiling them");
  field.compile();

  // Half of the tolerance for the fit, the rest is margin for what the check grid does not see.
  s.seconds_generate = seconds_since(start);
  const double target = 0.5 * r.tolerance / r.cell_size;
  const auto inside_wall = [&field, &worker](const Point& p) { return wall_at(field, worker, p.data()) < 0; };
  say(layout != nullptr ? "fitting the symmetry patches, building the solid"
                        : "cutting the wall into boxes, fitting their patches, building the solid");
  const WallBrep brep = layout != nullptr ? symmetry_wall(*layout, field, worker, r, target, inside_wall, s)
                                          : box_wall(field, worker, r, target, inside_wall, s);
  s.control_points = brep.control_points;
  s.expected_solids = brep.solids;

  // The exact wall volume needs only the wall's functions: it runs alongside the writing and the checks.
  std::future<ExactVolume> exact_volume = start_exact_wall_volume(field, r, s);
  say("writing STEP");
  auto t0 = Clock::now();
  const run::ScratchDir scratch("offsetgen-step");  // removed on exit (a loaded library's mapping stays)
  const fs::path file = scratch.path() / "wall.step";
  write_step(brep.solid, file.string(),
             fmt::format("offsetgen: {} wall, t = {} (cell units), {}x{}x{} cells of {} mm, tolerance {} mm; {}",
                         s.surface, s.thickness_text, r.cells[0], r.cells[1], r.cells[2], r.cell_size, r.tolerance,
                         request_metadata(r, s)),
             /*pcurves=*/layout == nullptr);  // box patches' trimming curves are known exactly
  const std::string bytes = read_bytes(file);
  s.bytes = long(bytes.size());
  s.seconds_write = seconds_since(t0);

  // The solid written is measured as it is in memory: reading the file back took longer than every
  // other stage together (4.6 of 12 s, diamond in box patches), and the tests read every file back
  // (tests/step) as `offsetgen check` does. The file must hold every solid and face of it.
  say("measuring");
  measure_solid(brep.solid, r, field, worker, exact_volume, s);
  if (s.failure.empty()) s.failure = file_holds_the_solid(bytes, brep.solid);
  if (s.failure.empty()) {
    write_file(r.output, bytes);
    s.written = true;
  }
  s.seconds_total = seconds_since(start);
  s.cpu_seconds = double(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  return s;
}

StepCheck check_step_file(const std::string& path, const std::function<void(const std::string&)>& progress) {
  const auto start = Clock::now();
  const std::clock_t cpu_start = std::clock();
  auto say = [&](const std::string& what) {
    if (progress) progress(what);
  };
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) throw InputError(fmt::format("{}: no such file", path));
  const std::string bytes = read_bytes(path);
  if (bytes.rfind("ISO-10303-21;", 0) != 0)
    throw InputError(fmt::format("{}: not a STEP file (it does not begin with ISO-10303-21;)", path));
  say("reading the file");
  StepContents contents;
  try {
    contents = read_step_contents(path);
  } catch (const std::runtime_error& e) {
    throw InputError(e.what());
  }
  StepCheck check;
  StepSummary& s = check.summary;
  check.request = request_from_description(contents.description, path, s.expected_solids);
  s.surface = surface_words(check.request.wall.generation);
  s.bytes = long(bytes.size());
  s.seconds_read = seconds_since(start);

  say("generating the walls it was made from");
  auto t0 = Clock::now();
  wall::WallField field(check.request.wall);
  wall::WallField::Worker worker(field);
  prepare_walls(field, worker, check.request, s);
  field.compile();
  s.seconds_generate = seconds_since(t0);
  say("measuring");
  std::future<ExactVolume> exact_volume = start_exact_wall_volume(field, check.request, s);
  measure_solid(contents.shape, check.request, field, worker, exact_volume, s);
  s.written = s.failure.empty();
  s.seconds_total = seconds_since(start);
  s.cpu_seconds = double(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  return check;
}

namespace {

// Box patches meet at edges traced on the boxes' faces: no mirror plane makes their normals agree.
bool layout_less(const StepSummary& s) { return s.patches != "symmetry patch"; }

// "0.1 cell (1 mm)", or for a graded wall "0.05 + 0.05*x cell (0.5 to 1.5 mm in the block)".
std::string thickness_words(const StepSummary& s, double cell_size) {
  if (!s.graded) return fmt::format("{} cell ({} mm", s.thickness_text, s.thickness * cell_size);
  return fmt::format("{} cell ({:.4g} to {:.4g} mm in the block", s.thickness_text, s.thickness_range[0] * cell_size,
                     s.thickness_range[1] * cell_size);
}

}  // namespace

std::string format_check_summary(const StepCheck& c, const std::string& path) {
  const StepSummary& s = c.summary;
  const StepRequest& r = c.request;
  std::string out = fmt::format(
      "offsetgen check: {}: {} wall, t = {}), {}x{}x{} cells of {} mm, tolerance {} mm (its header)\n", path, s.surface,
      thickness_words(s, r.cell_size), r.cells[0], r.cells[1], r.cells[2], r.cell_size, r.tolerance);
  out += fmt::format("  faces: {} B-spline, {} planar; {} control points ({:.0f} per cell); {} bytes\n",
                     s.bspline_faces, s.planar_faces, s.control_points, s.control_points_per_cell, s.bytes);
  out += fmt::format("  {}  solid: {}, {} solid{} ({} expected), {}\n",
                     s.valid && s.closed && s.solids == s.expected_solids ? "PASS" : "FAIL",
                     s.valid ? "valid (BRepCheck_Analyzer)" : "NOT valid", s.solids, s.solids == 1 ? "" : "s",
                     s.expected_solids, s.closed ? "each one closed shell" : "NOT closed");
  out += fmt::format(
      "  {}  deviation of the exact walls from the faces, {} points: max {:.3g} mm, mean {:.3g} mm (tolerance {} mm)\n",
      s.max_deviation <= r.tolerance ? "PASS" : "FAIL", s.deviation_points, s.max_deviation, s.mean_deviation,
      r.tolerance);
  const double rel = s.exact_volume > 0 ? (s.volume - s.exact_volume) / s.exact_volume : 0;
  out += fmt::format(
      "  {}  volume: {:.6f} mm^3; exact wall {:.6f} mm^3 (column quadrature, standard error {:.2g}); difference "
      "{:+.3g}% (at most {}%)\n",
      volume_agrees(s) ? "PASS" : "FAIL", s.volume, s.exact_volume, s.exact_volume_error, 100 * rel,
      100 * kVolumeTolerance);
  out += fmt::format("  time: {:.2f} s, {:.2f} s of CPU\n", s.seconds_total, s.cpu_seconds);
  out += s.written ? "offsetgen check: all checks passed\n" : "offsetgen check: FAILED: " + s.failure + "\n";
  return out;
}

std::string format_summary(const StepSummary& s, const StepRequest& r) {
  std::string out =
      fmt::format("offsetgen step: {}: {} wall, t = {}; curvature limit {:.4f} cell), {}x{}x{} cells of {} mm\n",
                  s.written ? r.output + " written" : "no file written", s.surface, thickness_words(s, r.cell_size),
                  s.thickness_limit, r.cells[0], r.cells[1], r.cells[2], r.cell_size);
  out += fmt::format(
      "  faces: {} B-spline (bicubic, {}x{} control points per {}), {} planar; {} control points "
      "({:.0f} per cell){}; {} bytes; {}\n",
      s.bspline_faces, s.patch_control_points, s.patch_control_points, s.patches, s.planar_faces, s.control_points,
      s.control_points_per_cell, s.graded ? ", each image fitted on its own (graded)" : "", s.bytes,
      s.graded || layout_less(s)
          ? "C0 edges"
          : fmt::format("largest normal jump across a patch edge {:.3f} degrees (C0 edges)", s.normal_jump));
  out += fmt::format("  solid: {}, {} solid{}, {}{}\n", s.valid ? "valid (BRepCheck_Analyzer)" : "NOT valid", s.solids,
                     s.solids == 1 ? "" : "s", s.closed ? "each one closed shell" : "NOT closed",
                     s.expected_solids == 1 ? ""
                                            : fmt::format(" (the block cuts the wall into {} pieces: the surface "
                                                          "crosses two of its corners)",
                                                          s.expected_solids));
  out += fmt::format(
      "  deviation of the exact walls from the faces, {} points measured: max {:.3g} mm, mean {:.3g} mm "
      "(tolerance {} mm; fit check {:.3g} mm)\n",
      s.deviation_points, s.max_deviation, s.mean_deviation, r.tolerance, s.fit_error);
  const double rel = s.exact_volume > 0 ? (s.volume - s.exact_volume) / s.exact_volume : 0;
  out += fmt::format(
      "  volume: {:.6f} mm^3; exact wall {:.6f} mm^3 (column quadrature, standard error {:.2g}); difference "
      "{:+.3g}%\n",
      s.volume, s.exact_volume, s.exact_volume_error, 100 * rel);
  out += fmt::format(
      "  time: {:.2f} s, {:.2f} s of CPU (generate and compile {:.2f}, fit {:.2f}, build {:.2f}, write {:.2f}, "
      "check {:.2f}, deviation {:.2f}; exact volume {:.2f} alongside the last three)\n",
      s.seconds_total, s.cpu_seconds, s.seconds_generate, s.seconds_fit, s.seconds_build, s.seconds_write,
      s.seconds_check, s.seconds_deviation, s.seconds_volume);
  if (!s.written) out += "  check failed: " + s.failure + "\n";
  return out;
}

}  // namespace offsetgen::step
