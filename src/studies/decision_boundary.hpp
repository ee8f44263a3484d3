// The zero level set of a function of two inputs, traced by marching squares, and the crossings
// of two such curves: the bonding boundaries Z = 0 of two particle sizes' logistic fits and
// their intersection, the calibrated (G_c, Gdot_c) (mpm-bonding-thesis.md §4.1.2, Figure 4.4;
// §5.1.1-5.1.2). Pure math; see docs/studies-math.md.
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <functional>
#include <iosfwd>
#include <optional>
#include <vector>

#include "studies/logistic_regression.hpp"

namespace coldspray::studies {

// How an axis is sampled and measured: uniformly in x, or uniformly in log10 x (x > 0).
enum class AxisScale { Linear, Log10 };

// A rectangle [x1_min, x1_max] x [x2_min, x2_max] in input units sampled by `nodes` x `nodes`
// grid points, spaced uniformly in each axis' plot coordinate p = x or log10 x. Geometry
// (interpolation, intersection, distances) is done in plot coordinates.
struct PlaneGrid {
  double x1_min = 0.0, x1_max = 1.0;
  double x2_min = 0.0, x2_max = 1.0;
  int nodes = 201;  // per axis, >= 2
  AxisScale scale1 = AxisScale::Linear;
  AxisScale scale2 = AxisScale::Linear;

  Eigen::Vector2d to_plot(const Eigen::Vector2d& x) const;    // (p1, p2)
  Eigen::Vector2d from_plot(const Eigen::Vector2d& p) const;  // back to input units
  // Plot coordinates rescaled so that the rectangle is the unit square.
  Eigen::Vector2d to_unit(const Eigen::Vector2d& x) const;
  Eigen::Vector2d from_unit(const Eigen::Vector2d& u) const;  // back to input units
  void validate() const;  // throws std::invalid_argument for an empty or unloggable rectangle
};

// A curve as points in input units, no two consecutive ones equal. A closed curve repeats its
// first point at its end.
using Polyline = std::vector<Eigen::Vector2d>;

struct Boundary {
  PlaneGrid grid;                // where the curves were traced
  std::vector<Polyline> curves;  // deterministic order, see trace_zero_contour
};

// The curves f(x1, x2) = 0 over the grid by marching squares: f at every node; a crossing on
// each cell edge whose end values differ in sign (f >= 0 counts as positive), placed by linear
// interpolation of f along the edge in plot coordinates; the crossings of each cell joined by
// segments (the two saddle cases split by the mean of the four corners); the segments chained
// into polylines. Order: open curves (ending on the rectangle's edge) first, each starting from
// its end at the lower-numbered grid edge, by that edge's number; then closed curves, by their
// lowest-numbered edge. Grid edges are numbered row by row from (x1_min, x2_min). Features
// smaller than a cell may be missed. Throws std::invalid_argument for a bad grid or a
// non-finite f.
Boundary trace_zero_contour(const std::function<double(double, double)>& f, const PlaneGrid& grid);

// The decision boundary Z = 0 (h = 0.5) of a logistic fit over the rectangle, on a grid whose
// axis scales follow the fit's input transforms (log10 transform -> Log10 axis).
Boundary decision_boundary(const LogisticFit& fit, double x1_min, double x1_max, double x2_min,
                           double x2_max, int nodes = 201);

struct Intersection {
  Eigen::Vector2d point;                   // input units
  std::size_t curve_a = 0, segment_a = 0;  // curve and segment (from its point segment_a) of A
  std::size_t curve_b = 0, segment_b = 0;
};

// All crossing points of the curves of A with those of B, by segment-segment intersection in
// the plot coordinates of `A.grid` (B's points are mapped with the same axis scales). Each
// crossing is reported once, also at a shared vertex; collinear overlapping segments give no
// point. Order: by curve of A, then by position along it.
std::vector<Intersection> intersect_boundaries(const Boundary& a, const Boundary& b);

// The same for two sets of polylines, measured in the plot coordinates of `frame`'s axis scales.
std::vector<Intersection> intersect_polylines(const std::vector<Polyline>& a,
                                              const std::vector<Polyline>& b,
                                              const PlaneGrid& frame);

// The crossing nearest `target` (input units), distance measured in `frame`'s unit square
// (so both axes weigh alike whatever their units); nullopt when there is none.
std::optional<Intersection> nearest_intersection(const std::vector<Intersection>& points,
                                                 const Eigen::Vector2d& target,
                                                 const PlaneGrid& frame);
// The first crossing in the order of intersect_boundaries; nullopt when there is none.
std::optional<Intersection> first_intersection(const std::vector<Intersection>& points);

// Where two sets of curves come closest: a point on each and the distance between them in
// `frame`'s unit square. When the curves cross, the distance is 0 and both points are a crossing.
// The midpoint (taken in plot coordinates) is the calibration's compromise when two sizes'
// boundaries do not cross (docs/studies-math.md). nullopt when either set has no segment.
struct ClosestApproach {
  Eigen::Vector2d on_a, on_b, midpoint;  // input units
  double distance = 0.0;                 // in the frame's unit square
};
std::optional<ClosestApproach> closest_approach(const std::vector<Polyline>& a,
                                                const std::vector<Polyline>& b,
                                                const PlaneGrid& frame);

// CSV with header `x1,x2,curve`, one row per point, curve = index into b.curves, for plotting.
void write_boundary_csv(std::ostream& out, const Boundary& b);
void write_boundary_csv(const std::filesystem::path& path, const Boundary& b);

}  // namespace coldspray::studies
