#include "studies/decision_boundary.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <limits>
#include <map>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <string>

#include "io/atomic_file.hpp"

namespace coldspray::studies {

namespace {

double to_axis(double x, AxisScale s) { return s == AxisScale::Log10 ? std::log10(x) : x; }
double from_axis(double p, AxisScale s) { return s == AxisScale::Log10 ? std::pow(10.0, p) : p; }

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a(0) * b(1) - a(1) * b(0);
}

// Where the lines P + t r and Q + u s meet, as (t, u); nullopt for parallel (or degenerate)
// segments, collinear ones included (docs/studies-math.md, Intersections).
std::optional<std::array<double, 2>> crossing_parameters(const Eigen::Vector2d& P,
                                                         const Eigen::Vector2d& r,
                                                         const Eigen::Vector2d& Q,
                                                         const Eigen::Vector2d& s) {
  const double denom = cross(r, s);
  if (std::abs(denom) <= 1e-14 * r.norm() * s.norm() || denom == 0.0) return std::nullopt;
  return std::array<double, 2>{cross(Q - P, s) / denom, cross(Q - P, r) / denom};
}

// Grid edges: horizontal (i, j)-(i+1, j) has number 2 (j N + i), vertical (i, j)-(i, j+1) has
// 2 (j N + i) + 1, so that numbers run row by row from the (x1_min, x2_min) corner.
using EdgeId = std::int64_t;

struct Sampled {
  int n = 0;
  Eigen::Vector2d p_min, p_max;  // plot coordinates of the rectangle's corners
  std::vector<double> f;         // f at node (i, j) is f[j n + i]

  Eigen::Vector2d node(int i, int j) const {
    const double s1 = static_cast<double>(i) / (n - 1), s2 = static_cast<double>(j) / (n - 1);
    return {p_min(0) + s1 * (p_max(0) - p_min(0)), p_min(1) + s2 * (p_max(1) - p_min(1))};
  }
  double value(int i, int j) const { return f[static_cast<std::size_t>(j) * n + i]; }
  EdgeId horizontal(int i, int j) const { return 2 * (static_cast<EdgeId>(j) * n + i); }
  EdgeId vertical(int i, int j) const { return 2 * (static_cast<EdgeId>(j) * n + i) + 1; }

  // Where f = 0 on the edge, by linear interpolation in plot coordinates. Only called for an
  // edge whose end values differ in sign, so fa - fb != 0.
  Eigen::Vector2d crossing(EdgeId e) const {
    const EdgeId cell = e / 2;
    const int i = static_cast<int>(cell % n), j = static_cast<int>(cell / n);
    const int i1 = (e % 2 == 0) ? i + 1 : i, j1 = (e % 2 == 0) ? j : j + 1;
    const double fa = value(i, j), fb = value(i1, j1);
    const double t = fa / (fa - fb);
    return node(i, j) + t * (node(i1, j1) - node(i, j));
  }
};

bool positive(double v) { return v >= 0.0; }

// The segments of one cell as pairs of edge numbers (marching squares).
void cell_segments(const Sampled& g, int i, int j, std::vector<std::array<EdgeId, 2>>& out) {
  const double c0 = g.value(i, j), c1 = g.value(i + 1, j), c2 = g.value(i + 1, j + 1),
               c3 = g.value(i, j + 1);
  const EdgeId bottom = g.horizontal(i, j), right = g.vertical(i + 1, j),
               top = g.horizontal(i, j + 1), left = g.vertical(i, j);
  std::array<EdgeId, 4> cut{};
  int count = 0;
  if (positive(c0) != positive(c1)) cut[count++] = bottom;
  if (positive(c1) != positive(c2)) cut[count++] = right;
  if (positive(c2) != positive(c3)) cut[count++] = top;
  if (positive(c3) != positive(c0)) cut[count++] = left;
  if (count == 2) {
    out.push_back({cut[0], cut[1]});
  } else if (count == 4) {
    // Saddle: c0, c2 share a sign and c1, c3 the other. If the cell centre (mean of the corners)
    // has c0's sign, c0 and c2 connect through it and the curves cut off corners c1 and c3.
    const bool centre = positive(0.25 * (c0 + c1 + c2 + c3));
    if (centre == positive(c0)) {
      out.push_back({bottom, right});
      out.push_back({top, left});
    } else {
      out.push_back({left, bottom});
      out.push_back({right, top});
    }
  }
}

// A crossing found while scanning segment pairs; `along` orders it on A's segment.
struct Candidate {
  Intersection hit;
  double along = 0.0;
};

}  // namespace

Eigen::Vector2d PlaneGrid::to_plot(const Eigen::Vector2d& x) const {
  return {to_axis(x(0), scale1), to_axis(x(1), scale2)};
}

Eigen::Vector2d PlaneGrid::from_plot(const Eigen::Vector2d& p) const {
  return {from_axis(p(0), scale1), from_axis(p(1), scale2)};
}

Eigen::Vector2d PlaneGrid::to_unit(const Eigen::Vector2d& x) const {
  const Eigen::Vector2d lo = to_plot({x1_min, x2_min}), hi = to_plot({x1_max, x2_max});
  return ((to_plot(x) - lo).array() / (hi - lo).array()).matrix();
}

Eigen::Vector2d PlaneGrid::from_unit(const Eigen::Vector2d& u) const {
  const Eigen::Vector2d lo = to_plot({x1_min, x2_min}), hi = to_plot({x1_max, x2_max});
  return from_plot(lo + u.cwiseProduct(hi - lo));
}

void PlaneGrid::validate() const {
  if (nodes < 2) throw std::invalid_argument("boundary grid: nodes must be >= 2");
  if (!(x1_min < x1_max) || !(x2_min < x2_max) || !std::isfinite(x1_min) ||
      !std::isfinite(x1_max) || !std::isfinite(x2_min) || !std::isfinite(x2_max))
    throw std::invalid_argument("boundary grid: need finite x1_min < x1_max and x2_min < x2_max");
  if ((scale1 == AxisScale::Log10 && !(x1_min > 0.0)) ||
      (scale2 == AxisScale::Log10 && !(x2_min > 0.0)))
    throw std::invalid_argument("boundary grid: a log10 axis needs a positive range");
}

Boundary trace_zero_contour(const std::function<double(double, double)>& f, const PlaneGrid& grid) {
  grid.validate();
  Sampled g;
  g.n = grid.nodes;
  g.p_min = grid.to_plot({grid.x1_min, grid.x2_min});
  g.p_max = grid.to_plot({grid.x1_max, grid.x2_max});
  g.f.resize(static_cast<std::size_t>(g.n) * g.n);
  for (int j = 0; j < g.n; ++j) {
    for (int i = 0; i < g.n; ++i) {
      const Eigen::Vector2d x = grid.from_plot(g.node(i, j));
      const double v = f(x(0), x(1));
      if (!std::isfinite(v))
        throw std::invalid_argument("boundary tracing: the function is not finite at (" +
                                    std::to_string(x(0)) + ", " + std::to_string(x(1)) + ")");
      g.f[static_cast<std::size_t>(j) * g.n + i] = v;
    }
  }

  std::vector<std::array<EdgeId, 2>> segments;
  for (int j = 0; j + 1 < g.n; ++j)
    for (int i = 0; i + 1 < g.n; ++i) cell_segments(g, i, j, segments);

  // Each crossed edge belongs to one segment (rectangle side) or two (interior).
  std::map<EdgeId, std::vector<std::size_t>> at_edge;
  for (std::size_t s = 0; s < segments.size(); ++s)
    for (EdgeId e : segments[s]) at_edge[e].push_back(s);

  std::vector<bool> used(segments.size(), false);
  Boundary out;
  out.grid = grid;
  auto point = [&](EdgeId e) { return grid.from_plot(g.crossing(e)); };
  // Follows unused segments from edge `e` until none is left; a closed walk ends back at its
  // start edge, whose point is then repeated.
  auto walk = [&](EdgeId e) {
    Polyline line{point(e)};
    for (;;) {
      const std::vector<std::size_t>& here = at_edge.at(e);
      auto next = std::find_if(here.begin(), here.end(), [&](std::size_t s) { return !used[s]; });
      if (next == here.end()) break;
      used[*next] = true;
      const auto& seg = segments[*next];
      e = seg[0] == e ? seg[1] : seg[0];
      // Where the curve passes through a node (f = 0 there), two edges give the same point.
      const Eigen::Vector2d x = point(e);
      if (x != line.back()) line.push_back(x);
    }
    out.curves.push_back(std::move(line));
  };
  for (const auto& [e, segs] : at_edge)
    if (segs.size() == 1 && !used[segs[0]]) walk(e);
  for (const auto& [e, segs] : at_edge)
    if (std::any_of(segs.begin(), segs.end(), [&](std::size_t s) { return !used[s]; })) walk(e);
  return out;
}

Boundary decision_boundary(const LogisticFit& fit, double x1_min, double x1_max, double x2_min,
                           double x2_max, int nodes) {
  PlaneGrid grid;
  grid.x1_min = x1_min;
  grid.x1_max = x1_max;
  grid.x2_min = x2_min;
  grid.x2_max = x2_max;
  grid.nodes = nodes;
  auto scale = [](InputTransform t) {
    return t == InputTransform::Log10 ? AxisScale::Log10 : AxisScale::Linear;
  };
  grid.scale1 = scale(fit.scaling.transform[0]);
  grid.scale2 = scale(fit.scaling.transform[1]);
  return trace_zero_contour([&fit](double x1, double x2) { return fit.z(x1, x2); }, grid);
}

std::vector<Intersection> intersect_polylines(const std::vector<Polyline>& a,
                                              const std::vector<Polyline>& b,
                                              const PlaneGrid& frame) {
  std::vector<std::vector<Eigen::Vector2d>> pb(b.size());
  for (std::size_t k = 0; k < b.size(); ++k)
    for (const Eigen::Vector2d& x : b[k]) pb[k].push_back(frame.to_plot(x));
  // End parameters a little outside [0, 1] so that a crossing at a vertex is not lost to
  // rounding; the duplicate it may cause on the neighbouring segment is removed below.
  constexpr double kSlack = 1e-12;
  std::vector<Candidate> found;
  for (std::size_t ca = 0; ca < a.size(); ++ca) {
    for (std::size_t sa = 0; sa + 1 < a[ca].size(); ++sa) {
      const Eigen::Vector2d P = frame.to_plot(a[ca][sa]);
      const Eigen::Vector2d r = frame.to_plot(a[ca][sa + 1]) - P;
      for (std::size_t cb = 0; cb < pb.size(); ++cb) {
        for (std::size_t sb = 0; sb + 1 < pb[cb].size(); ++sb) {
          const Eigen::Vector2d& Q = pb[cb][sb];
          const Eigen::Vector2d s = pb[cb][sb + 1] - Q;
          const auto tu = crossing_parameters(P, r, Q, s);
          if (!tu) continue;  // parallel: no single crossing point
          const auto [t, u] = *tu;
          if (t < -kSlack || t > 1.0 + kSlack || u < -kSlack || u > 1.0 + kSlack) continue;
          Candidate c;
          c.hit.point = frame.from_plot(P + std::clamp(t, 0.0, 1.0) * r);
          c.hit.curve_a = ca;
          c.hit.segment_a = sa;
          c.hit.curve_b = cb;
          c.hit.segment_b = sb;
          c.along = static_cast<double>(sa) + std::clamp(t, 0.0, 1.0);
          found.push_back(c);
        }
      }
    }
  }
  std::stable_sort(found.begin(), found.end(), [](const Candidate& x, const Candidate& y) {
    return x.hit.curve_a != y.hit.curve_a ? x.hit.curve_a < y.hit.curve_a : x.along < y.along;
  });
  // The same crossing seen from two segments that share a vertex (of A or of B) is kept once.
  constexpr double kSame = 1e-9;  // in the frame's unit square
  std::vector<Intersection> out;
  for (const Candidate& c : found) {
    const Eigen::Vector2d u = frame.to_unit(c.hit.point);
    const bool seen = std::any_of(out.begin(), out.end(), [&](const Intersection& k) {
      return (frame.to_unit(k.point) - u).norm() <= kSame;
    });
    if (!seen) out.push_back(c.hit);
  }
  return out;
}

std::vector<Intersection> intersect_boundaries(const Boundary& a, const Boundary& b) {
  return intersect_polylines(a.curves, b.curves, a.grid);
}

std::optional<Intersection> nearest_intersection(const std::vector<Intersection>& points,
                                                 const Eigen::Vector2d& target,
                                                 const PlaneGrid& frame) {
  std::optional<Intersection> best;
  double best_d = std::numeric_limits<double>::infinity();
  const Eigen::Vector2d t = frame.to_unit(target);
  for (const Intersection& p : points) {
    const double d = (frame.to_unit(p.point) - t).norm();
    if (d < best_d) {
      best_d = d;
      best = p;
    }
  }
  return best;
}

std::optional<Intersection> first_intersection(const std::vector<Intersection>& points) {
  if (points.empty()) return std::nullopt;
  return points.front();
}

namespace {

// The point of segment [p, q] nearest x (all in the same coordinates).
Eigen::Vector2d nearest_on_segment(const Eigen::Vector2d& x, const Eigen::Vector2d& p,
                                   const Eigen::Vector2d& q) {
  const Eigen::Vector2d d = q - p;
  const double length2 = d.squaredNorm();
  if (length2 == 0.0) return p;
  return p + std::clamp((x - p).dot(d) / length2, 0.0, 1.0) * d;
}

struct SegmentPair {
  Eigen::Vector2d on_a, on_b;  // unit-square coordinates
  double distance = 0.0;
};

// Two segments in the unit square: a crossing if they cross, else the nearest pair, which then
// has an end point of one of them as one of its points (also for parallel segments).
SegmentPair nearest_points(const Eigen::Vector2d& a0, const Eigen::Vector2d& a1,
                           const Eigen::Vector2d& b0, const Eigen::Vector2d& b1) {
  const Eigen::Vector2d r = a1 - a0;
  if (const auto tu = crossing_parameters(a0, r, b0, b1 - b0)) {
    const auto [t, u] = *tu;
    if (t >= 0.0 && t <= 1.0 && u >= 0.0 && u <= 1.0) {
      const Eigen::Vector2d x = a0 + t * r;
      return {x, x, 0.0};
    }
  }
  SegmentPair best{a0, nearest_on_segment(a0, b0, b1), 0.0};
  best.distance = (best.on_a - best.on_b).norm();
  auto consider = [&best](const Eigen::Vector2d& on_a, const Eigen::Vector2d& on_b) {
    const double d = (on_a - on_b).norm();
    if (d < best.distance) best = {on_a, on_b, d};
  };
  consider(a1, nearest_on_segment(a1, b0, b1));
  consider(nearest_on_segment(b0, a0, a1), b0);
  consider(nearest_on_segment(b1, a0, a1), b1);
  return best;
}

}  // namespace

std::optional<ClosestApproach> closest_approach(const std::vector<Polyline>& a,
                                                const std::vector<Polyline>& b,
                                                const PlaneGrid& frame) {
  auto to_unit = [&frame](const std::vector<Polyline>& curves) {
    std::vector<std::vector<Eigen::Vector2d>> u(curves.size());
    for (std::size_t k = 0; k < curves.size(); ++k)
      for (const Eigen::Vector2d& x : curves[k]) u[k].push_back(frame.to_unit(x));
    return u;
  };
  const auto ua = to_unit(a), ub = to_unit(b);
  std::optional<SegmentPair> best;
  for (const auto& ca : ua)
    for (std::size_t i = 0; i + 1 < ca.size(); ++i)
      for (const auto& cb : ub)
        for (std::size_t j = 0; j + 1 < cb.size(); ++j) {
          const SegmentPair p = nearest_points(ca[i], ca[i + 1], cb[j], cb[j + 1]);
          if (!best || p.distance < best->distance) best = p;
        }
  if (!best) return std::nullopt;
  return ClosestApproach{frame.from_unit(best->on_a), frame.from_unit(best->on_b),
                         frame.from_unit(0.5 * (best->on_a + best->on_b)), best->distance};
}

void write_boundary_csv(std::ostream& out, const Boundary& b) {
  out << "x1,x2,curve\n" << std::setprecision(17);
  for (std::size_t c = 0; c < b.curves.size(); ++c)
    for (const Eigen::Vector2d& x : b.curves[c]) out << x(0) << ',' << x(1) << ',' << c << '\n';
}

void write_boundary_csv(const std::filesystem::path& path, const Boundary& b) {
  io::write_atomically(path, [&b](std::ostream& out) { write_boundary_csv(out, b); });
}

}  // namespace coldspray::studies
