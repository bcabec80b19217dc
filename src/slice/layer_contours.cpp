#include "slice/layer_contours.h"

#include "numeric/root_finding.h"
#include "wall/layer_sampler.h"
#include "wall/part_value.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <stdexcept>

namespace offsetgen::slice {
namespace {

constexpr int kMargin = 2;              // pixels of the marching grid beyond each side of the box
constexpr double kRootEps = 1e-11;      // cell units: a refined root's bracket
constexpr int kBatchIterations = 64;    // regula falsi rounds before Brent takes over
constexpr int kVerifyRounds = 16;       // rounds of midpoint checks and splits
constexpr double kMaxChordPixels = 24;  // the longest chord the thinning makes, in pixels

Point2 lerp(const Point2& a, const Point2& b, double t) { return {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])}; }
double length(const Point2& a, const Point2& b) { return std::hypot(b[0] - a[0], b[1] - a[1]); }

double segment_distance(const Point2& p, const Point2& a, const Point2& b) {
  const double dx = b[0] - a[0], dy = b[1] - a[1];
  const double l2 = dx * dx + dy * dy;
  double t = l2 > 0 ? ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / l2 : 0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(p[0] - a[0] - t * dx, p[1] - a[1] - t * dy);
}

// The body's distance on the marching grid's blocks (LayerSetup::body): where each block lies, and d
// (pixels) of the Mixed ones.
struct BodyBlocks {
  int blocks_y = 0;
  std::vector<BodyLayer::Place> place;  // block (bi, bj) at bi * blocks_y + bj
  std::vector<int32_t> slot;            // a Mixed block's values at d[slot * 64]
  std::vector<double> d;
  BodyLayer::Place at(int i, int j, double& value) const {
    const size_t b = static_cast<size_t>(i / wall::kLayerBlock) * blocks_y + j / wall::kLayerBlock;
    if (place[b] == BodyLayer::Place::Mixed)
      value = d[static_cast<size_t>(slot[b]) * wall::kLayerBlockPixels +
                static_cast<size_t>((i % wall::kLayerBlock) * wall::kLayerBlock + j % wall::kLayerBlock)];
    return place[b];
  }
};

BodyBlocks body_blocks(const BodyLayer& body, const wall::LayerGrid& grid, const std::array<int, 2>& first, double z) {
  BodyBlocks out;
  const int bx = (grid.size[0] + wall::kLayerBlock - 1) / wall::kLayerBlock;
  out.blocks_y = (grid.size[1] + wall::kLayerBlock - 1) / wall::kLayerBlock;
  out.place.resize(static_cast<size_t>(bx) * out.blocks_y);
  out.slot.assign(out.place.size(), -1);
  BodyLayer::Query query(body);
  std::array<double, wall::kLayerBlockPixels> d{};
  for (int bi = 0; bi < bx; ++bi)
    for (int bj = 0; bj < out.blocks_y; ++bj) {
      const size_t b = static_cast<size_t>(bi) * out.blocks_y + bj;
      out.place[b] =
          body.block({first[0] + bi * wall::kLayerBlock, first[1] + bj * wall::kLayerBlock}, z, d.data(), query);
      if (out.place[b] != BodyLayer::Place::Mixed) continue;
      out.slot[b] = static_cast<int32_t>(out.d.size() / wall::kLayerBlockPixels);
      out.d.insert(out.d.end(), d.begin(), d.end());
    }
  return out;
}

// G in cell units, in batches: max(w, box), w the wall's level (negative inside) and box the distance
// to the block's box [0, NX] x [0, NY] (negative inside); or, with a body, the part from the body's
// distance and w (wall/part_value.h).
class Level {
 public:
  // With a body, `blocks` says where its distance is needed: only points in Mixed blocks get it.
  Level(const wall::WallField& field, const LayerSetup& s, const BodyBlocks* blocks = nullptr,
        const wall::LayerGrid* grid = nullptr)
      : field_(field), worker_(field), cells_(s.cells), z_(s.z), body_(s.body), blocks_(blocks) {
    if (body_) body_query_.emplace(*body_);
    if (grid) {
      pixel_ = grid->pixel;
      grid_origin_ = grid->origin;
      grid_size_ = grid->size;
    }
  }

  double box(const Point2& p) const {
    return std::max(std::max(-p[0], p[0] - cells_[0]), std::max(-p[1], p[1] - cells_[1]));
  }
  // The side of the box nearest outside: 0 x = 0, 1 x = NX, 2 y = 0, 3 y = NY.
  int side(const Point2& p) const {
    const double d[4] = {-p[0], p[0] - cells_[0], -p[1], p[1] - cells_[1]};
    return static_cast<int>(std::max_element(d, d + 4) - d);
  }

  // G at the points; w() holds the wall's level of the last batch.
  const std::vector<double>& operator()(const std::vector<Point2>& points) {
    const size_t n = points.size();
    x_.resize(n);
    y_.resize(n);
    zs_.assign(n, z_);
    w_.resize(n);
    g_.resize(n);
    for (size_t i = 0; i < n; ++i) {
      x_[i] = points[i][0];
      y_[i] = points[i][1];
    }
    if (n > 0) field_.walls(n, x_.data(), y_.data(), zs_.data(), w_.data(), worker_);
    if (body_) {
      body_distances(points);
      for (size_t i = 0; i < n; ++i) g_[i] = wall::part_value(d_[i], w_[i], body_->skin(), body_->fillet());
    } else {
      for (size_t i = 0; i < n; ++i) g_[i] = std::max(w_[i], box(points[i]));
    }
    evaluations += n;
    return g_;
  }
  const std::vector<double>& w() const { return w_; }
  double wall_at(const Point2& p) {
    double w = 0;
    field_.walls(1, &p[0], &p[1], &z_, &w, worker_);
    ++evaluations;
    return w;
  }
  double at(const Point2& p) {
    if (!body_) return std::max(wall_at(p), box(p));
    one_.assign(1, p);
    return (*this)(one_)[0];
  }

  size_t evaluations = 0;

 private:
  // d_ at the points: far from the body's surface (a block with no facet within reach, nearest pixel
  // first) the block's side is all that matters; elsewhere the exact distance.
  void body_distances(const std::vector<Point2>& points) {
    const size_t n = points.size();
    d_.resize(n);
    near_points_.clear();
    near_index_.clear();
    for (size_t i = 0; i < n; ++i) {
      BodyLayer::Place place = BodyLayer::Place::Mixed;
      if (blocks_) {
        const int pi = static_cast<int>(std::floor((points[i][0] - grid_origin_[0]) / pixel_));
        const int pj = static_cast<int>(std::floor((points[i][1] - grid_origin_[1]) / pixel_));
        if (pi >= 0 && pj >= 0 && pi < grid_size_[0] && pj < grid_size_[1]) {
          double unused = 0;
          place = blocks_->at(pi, pj, unused);
        }
      }
      if (place == BodyLayer::Place::Deep) {
        d_[i] = -kFarInside;
      } else if (place == BodyLayer::Place::Outside) {
        d_[i] = kFarInside;
      } else {
        near_points_.push_back(points[i]);
        near_index_.push_back(i);
      }
    }
    near_d_.resize(near_points_.size());
    if (!near_points_.empty()) body_->distances(near_points_, z_, near_d_.data(), *body_query_);
    for (size_t k = 0; k < near_index_.size(); ++k) d_[near_index_[k]] = near_d_[k];
  }
  static constexpr double kFarInside = 1e6;  // cell units: beyond every skin

  const wall::WallField& field_;
  wall::WallField::Worker worker_;
  std::array<int, 2> cells_;
  double z_;
  const BodyLayer* body_;
  const BodyBlocks* blocks_;
  double pixel_ = 1;
  std::array<double, 2> grid_origin_{};
  std::array<int, 2> grid_size_{};
  std::optional<BodyLayer::Query> body_query_;
  std::vector<double> x_, y_, zs_, w_, g_, d_, near_d_;
  std::vector<Point2> near_points_;
  std::vector<size_t> near_index_;
  std::vector<Point2> one_;
};

// A sign change of G on the segment a -> b: G(a) = fa < 0 <= G(b) = fb (any values of those signs).
struct Bracket {
  Point2 a, b;
  double fa, fb;
};

// The roots of G on the segments, to eps (cell units): regula falsi with the Illinois step, all segments in one
// batch per round, a bisection where a bracket stops halving; Brent's method for any left over.
std::vector<Point2> refine_roots(Level& level, const std::vector<Bracket>& brackets, double eps = kRootEps) {
  struct State {
    double ta = 0, tb = 1, fa = 0, fb = 0, true_fa = 0, true_fb = 0, width_before = 1, t = 0;
    int kept = 0;  // -1: a moved last, +1: b moved last
    bool done = false;
  };
  const size_t n = brackets.size();
  std::vector<State> s(n);
  std::vector<Point2> roots(n);
  for (size_t i = 0; i < n; ++i) {
    s[i].fa = s[i].true_fa = brackets[i].fa;
    s[i].fb = s[i].true_fb = brackets[i].fb;
    if (brackets[i].fb == 0) {
      s[i].done = true;
      s[i].t = 1;
    }
  }
  std::vector<size_t> active;
  std::vector<Point2> points;
  for (int round = 0; round < kBatchIterations; ++round) {
    active.clear();
    points.clear();
    for (size_t i = 0; i < n; ++i) {
      State& st = s[i];
      if (st.done) continue;
      const double len = length(brackets[i].a, brackets[i].b);
      if ((st.tb - st.ta) * len <= eps) {
        st.done = true;
        st.t = 0.5 * (st.ta + st.tb);
        continue;
      }
      double t = (st.ta * st.fb - st.tb * st.fa) / (st.fb - st.fa);
      if (round % 4 == 3) {
        // Bisect where the bracket did not halve over the last rounds.
        if (st.tb - st.ta > 0.5 * st.width_before) t = 0.5 * (st.ta + st.tb);
        st.width_before = st.tb - st.ta;
      }
      if (!(t > st.ta && t < st.tb)) t = 0.5 * (st.ta + st.tb);
      st.t = t;
      active.push_back(i);
      points.push_back(lerp(brackets[i].a, brackets[i].b, t));
    }
    if (active.empty()) break;
    const std::vector<double>& g = level(points);
    for (size_t k = 0; k < active.size(); ++k) {
      const size_t i = active[k];
      State& st = s[i];
      const double f = g[k];
      // Close enough when the root is within eps of t by the bracket's secant slope (G is smooth
      // there: a step of regula falsi is a Newton step to within the slope's error).
      const double len = length(brackets[i].a, brackets[i].b);
      const double slope = (st.true_fb - st.true_fa) / ((st.tb - st.ta) * len);
      if (f == 0 || std::abs(f) <= 0.1 * eps * slope) {
        st.done = true;
      } else if (f < 0) {
        st.ta = st.t;
        st.fa = st.true_fa = f;
        if (st.kept == -1) st.fb *= 0.5;
        st.kept = -1;
      } else {
        st.tb = st.t;
        st.fb = st.true_fb = f;
        if (st.kept == 1) st.fa *= 0.5;
        st.kept = 1;
      }
    }
  }
  for (size_t i = 0; i < n; ++i) {
    State& st = s[i];
    if (!st.done) {
      const Bracket& b = brackets[i];
      st.t = numeric::brent_root([&](double t) { return level.at(lerp(b.a, b.b, t)); }, st.ta, st.tb, st.true_fa,
                                 st.true_fb);
    }
    roots[i] = lerp(brackets[i].a, brackets[i].b, st.t);
  }
  return roots;
}

// A dense loop's point: where it lies (cell units), and what it is.
enum class Kind { Wall, Side, Corner };
struct DensePoint {
  Point2 p;
  Kind kind = Kind::Wall;
  int side = -1;          // Side: which side of the box
  int32_t estimate = -1;  // p is a crossing's linear estimate, its bracket's index; -1: p is exact
};

// A thread's buffers, reused from layer to layer: allocated once, they cost no page faults after the
// first layer.
struct Scratch {
  std::vector<float> values;
  std::vector<int32_t> next, crossing;
  std::vector<uint8_t> seen;
};
Scratch& scratch() {
  static thread_local Scratch s;
  return s;
}

// The marching grid of one layer: pixel (i, j) centred at ((first_x + i + 1/2) p, (first_y + j + 1/2) p).
class MarchingGrid {
 public:
  MarchingGrid(const wall::SampledLayer& layer, const LayerSetup& s, const wall::LayerGrid& grid,
               const std::array<int, 2>& first, const BodyBlocks* body)
      : nx_(grid.size[0]), ny_(grid.size[1]), first_(first), pixel_(grid.pixel), values_(scratch().values) {
    values_.assign(static_cast<size_t>(nx_) * ny_, layer.background);
    auto fill = [&](const std::array<int, 2>& origin, const std::vector<float>* block) {
      for (int i = 0; i < wall::kLayerBlock; ++i)
        for (int j = 0; j < wall::kLayerBlock; ++j) {
          const int gi = origin[0] + i, gj = origin[1] + j;
          if (gi >= nx_ || gj >= ny_) continue;
          values_[index(gi, gj)] = block ? (*block)[static_cast<size_t>(i * wall::kLayerBlock + j)] : -layer.background;
        }
    };
    for (const auto& o : layer.solid) fill(o, nullptr);
    for (const auto& b : layer.blocks) fill(b.origin, &b.values);
    if (body) {
      // G = the part from d and w, in pixels (w is +background where it was not needed).
      const double skin = s.body->skin() * s.pixels_per_cell, fillet = s.body->fillet() * s.pixels_per_cell;
      const double bg = layer.background;
      for (int i = 0; i < nx_; ++i)
        for (int j = 0; j < ny_; ++j) {
          double d = 0;
          const BodyLayer::Place place = body->at(i, j, d);
          float& v = values_[index(i, j)];
          if (place == BodyLayer::Place::Outside)
            v = layer.background;
          else if (place == BodyLayer::Place::Mixed)
            v = static_cast<float>(std::clamp(wall::part_value(d, v, skin, fillet), -bg, bg));
        }
      return;
    }
    // G = max(w, box), in pixels.
    for (int i = 0; i < nx_; ++i)
      for (int j = 0; j < ny_; ++j) {
        const double x = first_[0] + i + 0.5, y = first_[1] + j + 0.5;
        const double box = std::max(std::max(-x, x - s.cells[0] * s.pixels_per_cell),
                                    std::max(-y, y - s.cells[1] * s.pixels_per_cell));
        float& v = values_[index(i, j)];
        v = std::max(v, static_cast<float>(box));
      }
  }
  size_t index(int i, int j) const { return static_cast<size_t>(i) * ny_ + j; }
  float value(int i, int j) const { return values_[index(i, j)]; }
  bool inside(int i, int j) const { return values_[index(i, j)] < 0; }
  Point2 centre(int i, int j) const { return {(first_[0] + i + 0.5) * pixel_, (first_[1] + j + 0.5) * pixel_}; }
  // The centre of the square between pixels (i, j) and (i + 1, j + 1).
  Point2 corner(int i, int j) const { return {(first_[0] + i + 1.0) * pixel_, (first_[1] + j + 1.0) * pixel_}; }
  int nx() const { return nx_; }
  int ny() const { return ny_; }
  double pixel() const { return pixel_; }

  // Edges: 2 (i ny + j) from pixel (i, j) to (i + 1, j); + 1 from (i, j) to (i, j + 1).
  size_t edge(int i, int j, int vertical) const { return 2 * index(i, j) + static_cast<size_t>(vertical); }
  std::array<int, 4> edge_pixels(size_t e) const {
    const auto k = static_cast<int>(e / 2);
    const int i = k / ny_, j = k % ny_;
    return e % 2 == 0 ? std::array<int, 4>{i, j, i + 1, j} : std::array<int, 4>{i, j, i, j + 1};
  }

 private:
  int nx_, ny_;
  std::array<int, 2> first_;
  double pixel_;
  std::vector<float>& values_;
};

// Marching squares with the solid on the left of every segment: next[e] is the edge where the contour
// leaves the cell it enters by edge e (edge indices as MarchingGrid::edge); -1 where it does not cross.
const std::vector<int32_t>& march(const MarchingGrid& g, Level& level) {
  std::vector<int32_t>& next = scratch().next;
  next.assign(2 * static_cast<size_t>(g.nx()) * g.ny(), -1);
  // Saddle cells first, decided by G at their centre (one batch).
  std::vector<std::array<int, 2>> saddles;
  std::vector<Point2> centres;
  auto corners = [&](int i, int j) {
    return std::array<bool, 4>{g.inside(i, j), g.inside(i + 1, j), g.inside(i + 1, j + 1), g.inside(i, j + 1)};
  };
  for (int i = 0; i + 1 < g.nx(); ++i)
    for (int j = 0; j + 1 < g.ny(); ++j) {
      const auto c = corners(i, j);
      if (c[0] == c[2] && c[1] == c[3] && c[0] != c[1]) {
        saddles.push_back({i, j});
        centres.push_back(g.corner(i, j));
      }
    }
  const std::vector<double> centre_values = level(centres);
  size_t saddle = 0;
  for (int i = 0; i + 1 < g.nx(); ++i)
    for (int j = 0; j + 1 < g.ny(); ++j) {
      const auto c = corners(i, j);
      const int count = int(c[0]) + int(c[1]) + int(c[2]) + int(c[3]);
      if (count == 0 || count == 4) continue;
      // The cell's edges counter-clockwise: bottom, right, top, left.
      const size_t edges[4] = {g.edge(i, j, 0), g.edge(i + 1, j, 1), g.edge(i, j + 1, 0), g.edge(i, j, 1)};
      const bool is_saddle = c[0] == c[2] && c[1] == c[3];
      bool centre_inside = false;
      if (is_saddle) centre_inside = centre_values[saddle++] < 0;
      for (int k = 0; k < 4; ++k) {
        if (!(c[k] && !c[(k + 1) % 4])) continue;  // the contour enters the outside here: a start
        int end = -1;
        if (is_saddle) {
          end = centre_inside ? (k + 1) % 4 : (k + 3) % 4;
        } else {
          for (int m = 0; m < 4; ++m)
            if (!c[m] && c[(m + 1) % 4]) end = m;
        }
        next[edges[k]] = static_cast<int32_t>(edges[end]);
      }
    }
  return next;
}

// The corner where the wall meets side `side` of the box, between a point on that side (u_side along
// it) and a wall point (u_wall): the root of w along the side, searched from the side point towards
// the wall point over three pixels. nullopt when no sign change is found.
std::optional<Point2> side_corner(Level& level, const LayerSetup& s, int side, const Point2& on_side,
                                  const Point2& wall, double pixel) {
  const int along = side < 2 ? 1 : 0;  // the coordinate that runs along the side
  const double fixed = side == 0 || side == 2 ? 0.0 : double(s.cells[side < 2 ? 0 : 1]);
  auto at = [&](double u) {
    Point2 p{};
    p[along] = u;
    p[1 - along] = fixed;
    return p;
  };
  const double u0 = on_side[along];
  const double direction = wall[along] > u0 ? 1.0 : -1.0;
  double prev = u0, fprev = level.wall_at(at(u0));
  if (fprev >= 0) return std::nullopt;
  const double end = direction > 0 ? double(s.cells[along]) : 0.0;  // the side ends at the box's corner
  for (int k = 1; k <= 12 && prev != end; ++k) {
    const double u = direction > 0 ? std::min(end, u0 + k * pixel / 4) : std::max(end, u0 - k * pixel / 4);
    const double f = level.wall_at(at(u));
    if (f >= 0) {
      const double root = numeric::brent_root([&](double v) { return level.wall_at(at(v)); }, prev, u, fprev, f);
      return at(root);
    }
    prev = u;
    fprev = f;
  }
  return std::nullopt;
}

// Where side_corner finds no root before the side ends: the box's corner at that end, if it is inside
// the wall, and the corner where the wall meets the adjacent side (searched from the box's corner
// towards the wall point). Empty when neither is found.
std::vector<Point2> around_corner(Level& level, const LayerSetup& s, const DensePoint& side, const Point2& wall,
                                  double pixel) {
  const int along = side.side < 2 ? 1 : 0;
  const double fixed = side.side == 0 || side.side == 2 ? 0.0 : double(s.cells[1 - along]);
  const double end = wall[along] > side.p[along] ? double(s.cells[along]) : 0.0;
  Point2 corner{};
  corner[along] = end;
  corner[1 - along] = fixed;
  if (level.wall_at(corner) >= 0) return {};
  // The adjacent side: the one at u = end.
  const int next = along == 1 ? (end == 0 ? 2 : 3) : (end == 0 ? 0 : 1);
  const auto c = side_corner(level, s, next, corner, wall, pixel);
  if (!c) return {};
  return {corner, *c};
}

// The dense loop with the corners put in: where a wall point and a side point meet, and where two
// sides meet.
std::vector<DensePoint> with_corners(std::vector<DensePoint> loop, Level& level, const LayerSetup& s, double pixel) {
  std::vector<DensePoint> out;
  const size_t n = loop.size();
  for (size_t k = 0; k < n; ++k) {
    const DensePoint& a = loop[k];
    const DensePoint& b = loop[(k + 1) % n];
    out.push_back(a);
    if (a.kind == Kind::Side && b.kind == Kind::Side && a.side != b.side && (a.side < 2) != (b.side < 2)) {
      // Two sides: their corner, where it is inside the wall; else the wall cuts the corner off, and
      // meets each side on the way.
      const int xs = a.side < 2 ? a.side : b.side, ys = a.side < 2 ? b.side : a.side;
      const Point2 corner{xs == 0 ? 0.0 : double(s.cells[0]), ys == 2 ? 0.0 : double(s.cells[1])};
      if (level.wall_at(corner) < 0) {
        out.push_back({corner, Kind::Corner, -1});
      } else {
        if (const auto c = side_corner(level, s, a.side, a.p, corner, pixel)) out.push_back({*c, Kind::Corner, -1});
        if (const auto c = side_corner(level, s, b.side, b.p, corner, pixel)) out.push_back({*c, Kind::Corner, -1});
      }
    } else if ((a.kind == Kind::Side) != (b.kind == Kind::Side) && a.kind != Kind::Corner && b.kind != Kind::Corner) {
      const DensePoint& side = a.kind == Kind::Side ? a : b;
      const DensePoint& wall = a.kind == Kind::Side ? b : a;
      if (const auto c = side_corner(level, s, side.side, side.p, wall.p, pixel)) {
        out.push_back({*c, Kind::Corner, -1});
      } else if (const auto around = around_corner(level, s, side, wall.p, pixel); !around.empty()) {
        // The side ends inside the wall: the box's corner, then the wall meets the next side. In the
        // loop's order: side, corner, wall corner, wall (or the reverse).
        if (a.kind == Kind::Side) {
          for (const Point2& p : around) out.push_back({p, Kind::Corner, -1});
        } else {
          for (auto it = around.rbegin(); it != around.rend(); ++it) out.push_back({*it, Kind::Corner, -1});
        }
      }
    }
  }
  return out;
}

// Thins a dense loop: from each kept point, the farthest point such that every dense point between
// lies within `tol` of the chord (and the chord is at most `max_chord`); corners and three spread
// points are always kept.
std::vector<DensePoint> thin(const std::vector<DensePoint>& loop, double tol, double max_chord) {
  const size_t n = loop.size();
  if (n < 6) return loop;
  std::vector<size_t> fixed;
  for (size_t k = 0; k < n; ++k)
    if (loop[k].kind == Kind::Corner) fixed.push_back(k);
  size_t first = fixed.empty() ? 0 : fixed.front();
  // Indices from `first`, cyclic; the three spread points keep a small loop a polygon.
  std::vector<bool> must(n, false);
  for (size_t k : fixed) must[(k + n - first) % n] = true;
  must[0] = true;
  must[n / 3] = true;
  must[2 * n / 3] = true;
  auto at = [&](size_t k) -> const Point2& { return loop[(k + first) % n].p; };
  std::vector<DensePoint> kept;
  size_t i = 0;
  while (i < n) {
    kept.push_back(loop[(i + first) % n]);
    size_t end = i + 1;
    while (end < n && !must[end]) ++end;  // the next fixed point (n: back to the start)
    size_t best = i + 1;
    for (size_t j = i + 2; j <= end; ++j) {
      if (length(at(i), at(j)) > max_chord) break;
      bool ok = true;
      for (size_t k = i + 1; k < j && ok; ++k) ok = segment_distance(at(k), at(i), at(j)) <= tol;
      if (!ok) break;
      best = j;
    }
    i = best;
  }
  return kept;
}

// Checks every chord at its midpoint: the contour's point along the chord's normal, within `tol` on
// either side (the chord passes; its deviation recorded), or farther (that point becomes a vertex and
// both halves are checked again). Cell units.
void verify_chords(std::vector<std::vector<Point2>>& loops, Level& level, double tol, double pixel,
                   LayerContours& out) {
  struct Chord {
    size_t loop, index;
    Point2 mid, normal;
    double reach;
  };
  std::vector<std::vector<uint8_t>> pending(loops.size());
  for (size_t l = 0; l < loops.size(); ++l) pending[l].assign(loops[l].size(), 1);
  double max_dev = 0;
  for (int round = 0; round < kVerifyRounds; ++round) {
    std::vector<Chord> chords;
    for (size_t l = 0; l < loops.size(); ++l)
      for (size_t k = 0; k < loops[l].size(); ++k) {
        if (!pending[l][k]) continue;
        const Point2& a = loops[l][k];
        const Point2& b = loops[l][(k + 1) % loops[l].size()];
        const double len = length(a, b);
        if (len == 0) {
          pending[l][k] = 0;
          continue;
        }
        chords.push_back(
            {l, k, lerp(a, b, 0.5), {-(b[1] - a[1]) / len, (b[0] - a[0]) / len}, std::max(len, 2 * pixel)});
      }
    if (chords.empty()) break;
    // Within tol: a sign change of G between mid - tol n and mid + tol n. The deviation is where the
    // line through the two values crosses zero (G is all but linear over 2 tol).
    std::vector<Point2> probes;
    for (const Chord& c : chords) {
      probes.push_back({c.mid[0] - tol * c.normal[0], c.mid[1] - tol * c.normal[1]});
      probes.push_back({c.mid[0] + tol * c.normal[0], c.mid[1] + tol * c.normal[1]});
    }
    const std::vector<double> g = level(probes);
    std::vector<Bracket> far;
    std::vector<size_t> far_chord;
    std::vector<size_t> searching;
    for (size_t c = 0; c < chords.size(); ++c) {
      const double lo = g[2 * c], hi = g[2 * c + 1];
      if ((lo < 0) != (hi < 0)) {
        max_dev = std::max(max_dev, std::abs(tol * (lo + hi) / (hi - lo)));
        pending[chords[c].loop][chords[c].index] = 0;
      } else {
        searching.push_back(c);
      }
    }
    // The others: the contour along the normal, in growing steps (both ways) up to the chord's reach.
    std::vector<double> step(chords.size(), tol), fmid(chords.size(), 0);
    for (size_t c : searching) fmid[c] = g[2 * c];  // G's sign out to +-tol
    std::vector<size_t> still = searching;
    std::vector<Point2> found_roots;
    while (!still.empty()) {
      std::vector<Point2> pts;
      std::vector<size_t> next_still;
      for (size_t c : still) {
        const double s2 = 2 * step[c];
        pts.push_back({chords[c].mid[0] - s2 * chords[c].normal[0], chords[c].mid[1] - s2 * chords[c].normal[1]});
        pts.push_back({chords[c].mid[0] + s2 * chords[c].normal[0], chords[c].mid[1] + s2 * chords[c].normal[1]});
      }
      const std::vector<double> gs = level(pts);
      for (size_t k = 0; k < still.size(); ++k) {
        const size_t c = still[k];
        const Chord& ch = chords[c];
        const double s = step[c], s2 = 2 * s, m = fmid[c];
        bool done = false;
        for (int dir = -1; dir <= 1 && !done; dir += 2) {
          const double f = gs[2 * k + (dir > 0 ? 1 : 0)];
          if ((f < 0) != (m < 0)) {
            // G at +-s had the midpoint's sign (else the search had stopped there): the root lies
            // between s and 2 s; the midpoint's value stands in for G(s) in the first secant step.
            const Point2 inner{ch.mid[0] + dir * s * ch.normal[0], ch.mid[1] + dir * s * ch.normal[1]};
            const Point2& outer = pts[2 * k + (dir > 0 ? 1 : 0)];
            far.push_back(m < 0 ? Bracket{inner, outer, m, f} : Bracket{outer, inner, f, m});
            far_chord.push_back(c);
            done = true;
          }
        }
        if (!done) {
          step[c] = s2;
          if (2 * s2 <= ch.reach)
            next_still.push_back(c);
          else
            pending[ch.loop][ch.index] = 0, ++out.unverified_chords;
        }
      }
      still.swap(next_still);
    }
    const std::vector<Point2> far_roots = refine_roots(level, far);
    // Split the chords that failed at their projected midpoints.
    std::vector<std::vector<std::pair<size_t, Point2>>> inserts(loops.size());
    for (size_t k = 0; k < far.size(); ++k) {
      const Chord& c = chords[far_chord[k]];
      inserts[c.loop].push_back({c.index, far_roots[k]});
    }
    for (size_t l = 0; l < loops.size(); ++l) {
      if (inserts[l].empty()) continue;
      std::sort(inserts[l].begin(), inserts[l].end(), [](const auto& a, const auto& b) { return a.first < b.first; });
      std::vector<Point2> points;
      std::vector<uint8_t> flags;
      size_t next = 0;
      for (size_t k = 0; k < loops[l].size(); ++k) {
        points.push_back(loops[l][k]);
        if (next < inserts[l].size() && inserts[l][next].first == k) {
          flags.push_back(1);
          points.push_back(inserts[l][next].second);
          flags.push_back(1);
          ++next;
        } else {
          flags.push_back(pending[l][k]);
        }
      }
      loops[l].swap(points);
      pending[l].swap(flags);
    }
  }
  for (const auto& p : pending)
    for (uint8_t f : p) out.unverified_chords += f;
  out.max_deviation = std::max(out.max_deviation, max_dev);
}

}  // namespace

double polygon_area(const std::vector<Point2>& p) {
  double a = 0;
  for (size_t k = 0; k < p.size(); ++k) {
    const Point2& u = p[k];
    const Point2& v = p[(k + 1) % p.size()];
    a += u[0] * v[1] - v[0] * u[1];
  }
  return 0.5 * a;
}

bool on_box_side(const LayerSetup& s, const Point2& mm, double eps_mm) {
  const double x = mm[0], y = mm[1], wx = s.cells[0] * s.cell_size, wy = s.cells[1] * s.cell_size;
  return std::abs(x) <= eps_mm || std::abs(x - wx) <= eps_mm || std::abs(y) <= eps_mm || std::abs(y - wy) <= eps_mm;
}

LayerContours layer_contours(const wall::WallField& field, const LayerSetup& s) {
  LayerContours out;
  wall::LayerGrid grid;
  grid.z = s.z;
  grid.pixel = 1.0 / s.pixels_per_cell;
  std::array<int, 2> first{-kMargin, -kMargin};
  grid.size = {s.cells[0] * s.pixels_per_cell + 2 * kMargin, s.cells[1] * s.pixels_per_cell + 2 * kMargin};
  if (s.body) {
    first = s.body->first_pixel();
    grid.size = s.body->pixels();
  }
  grid.origin = {first[0] * grid.pixel, first[1] * grid.pixel};
  if (2.0 * grid.size[0] * grid.size[1] >= 2.0e9) throw std::length_error("layer grid too large");
  // With a body, the wall is sampled only where the part depends on it: in the core and near its surface.
  std::optional<BodyBlocks> body;
  wall::BlockFilter wanted;
  if (s.body) {
    body = body_blocks(*s.body, grid, first, s.z);
    const double skin = s.body->skin() * s.pixels_per_cell, fillet = s.body->fillet() * s.pixels_per_cell;
    wanted = [&](const std::array<int, 2>& origin) {
      const size_t b =
          static_cast<size_t>(origin[0] / wall::kLayerBlock) * body->blocks_y + origin[1] / wall::kLayerBlock;
      if (body->place[b] != BodyLayer::Place::Mixed) return body->place[b] == BodyLayer::Place::Deep;
      const double* d = &body->d[static_cast<size_t>(body->slot[b]) * wall::kLayerBlockPixels];
      return wall::wall_matters(*std::min_element(d, d + wall::kLayerBlockPixels), skin, fillet, 3.0);
    };
  }
  const wall::SampledLayer sampled = wall::sample_layer(field, grid, s.reach, s.use_field_bound, s.threads, {}, wanted);
  out.samples = sampled.samples;
  const MarchingGrid g(sampled, s, grid, first, body ? &*body : nullptr);
  Level level(field, s, body ? &*body : nullptr, &grid);
  const std::vector<int32_t>& next = march(g, level);

  // Every crossing's bracket, inside end first, and its linear estimate.
  std::vector<int32_t>& crossing = scratch().crossing;
  crossing.assign(next.size(), -1);
  std::vector<Bracket> brackets;
  std::vector<Point2> estimates;
  for (size_t e = 0; e < next.size(); ++e) {
    if (next[e] < 0) continue;
    const auto px = g.edge_pixels(e);
    const double fa = g.value(px[0], px[1]) * g.pixel(), fb = g.value(px[2], px[3]) * g.pixel();
    const Point2 a = g.centre(px[0], px[1]), b = g.centre(px[2], px[3]);
    crossing[e] = static_cast<int32_t>(brackets.size());
    brackets.push_back(fa < 0 ? Bracket{a, b, fa, fb} : Bracket{b, a, fb, fa});
    const Bracket& br = brackets.back();
    estimates.push_back(lerp(br.a, br.b, br.fa / (br.fa - br.fb)));
  }
  // Near the box's sides every crossing is refined at once onto G = 0, and its kind found (on a side
  // G = box >= w): the corners are found from them. Elsewhere the thinning works on the estimates,
  // and only the crossings it keeps are refined.
  std::vector<Bracket> near_brackets;
  std::vector<size_t> near_index;
  for (size_t k = 0; k < brackets.size() && !s.body; ++k)
    if (level.box(estimates[k]) > -3 * g.pixel()) {
      near_brackets.push_back(brackets[k]);
      near_index.push_back(k);
    }
  const std::vector<Point2> near_roots = refine_roots(level, near_brackets);
  level(near_roots);
  std::vector<uint8_t> exact(brackets.size(), 0), on_side(brackets.size(), 0);
  for (size_t k = 0; k < near_index.size(); ++k) {
    estimates[near_index[k]] = near_roots[k];
    exact[near_index[k]] = 1;
    on_side[near_index[k]] = level.box(near_roots[k]) > level.w()[k];
  }

  // Loops of crossings, in the order of their first edge.
  std::vector<uint8_t>& seen = scratch().seen;
  seen.assign(next.size(), 0);
  const double tol = s.tolerance / s.cell_size;
  std::vector<std::vector<DensePoint>> thinned;
  for (size_t e = 0; e < next.size(); ++e) {
    if (next[e] < 0 || seen[e]) continue;
    std::vector<DensePoint> dense;
    for (size_t k = e; !seen[k]; k = static_cast<size_t>(next[k])) {
      seen[k] = 1;
      const auto c = static_cast<size_t>(crossing[k]);
      const Point2& p = estimates[c];
      DensePoint d{p, Kind::Wall, -1, exact[c] ? -1 : static_cast<int32_t>(c)};
      if (on_side[c]) {
        d.kind = Kind::Side;
        d.side = level.side(p);
      }
      dense.push_back(d);
      if (next[k] < 0) throw std::logic_error("marching squares: an open contour");
    }
    if (!s.body) dense = with_corners(std::move(dense), level, s, g.pixel());
    thinned.push_back(thin(dense, 0.5 * tol, kMaxChordPixels * g.pixel()));
  }
  // The kept estimates refined onto G = 0.
  std::vector<Bracket> kept;
  for (const auto& loop : thinned)
    for (const DensePoint& d : loop)
      if (d.estimate >= 0) kept.push_back(brackets[static_cast<size_t>(d.estimate)]);
  const std::vector<Point2> kept_roots = refine_roots(level, kept);
  std::vector<std::vector<Point2>> loops;
  size_t next_root = 0;
  for (const auto& loop : thinned) {
    std::vector<Point2> points;
    for (const DensePoint& d : loop) points.push_back(d.estimate >= 0 ? kept_roots[next_root++] : d.p);
    loops.push_back(std::move(points));
  }
  verify_chords(loops, level, tol, g.pixel(), out);
  out.max_deviation *= s.cell_size;
  out.refine_evaluations = level.evaluations;
  for (auto& l : loops) {
    Loop loop;
    loop.points.reserve(l.size());
    for (const Point2& p : l) loop.points.push_back({p[0] * s.cell_size, p[1] * s.cell_size});
    loop.area = polygon_area(loop.points);
    if (std::abs(loop.area) < s.tiny_area || loop.points.size() < 3) {
      ++out.tiny_loops;
      continue;
    }
    out.vertices += loop.points.size();
    out.loops.push_back(std::move(loop));
  }
  return out;
}

}  // namespace offsetgen::slice
