// Marching squares on analytic functions, and the crossings of two curves against the analytic
// points.
#include "studies/decision_boundary.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>

#include "read_text.hpp"
#include "temp_dir.hpp"

namespace coldspray::studies {
namespace {

PlaneGrid square(double half, int nodes) {
  PlaneGrid g;
  g.x1_min = g.x2_min = -half;
  g.x1_max = g.x2_max = half;
  g.nodes = nodes;
  return g;
}

double circle(double x1, double x2) { return x1 * x1 + x2 * x2 - 1.0; }

TEST(StudiesBoundary, TracesACircleAsOneClosedCurve) {
  const PlaneGrid g = square(2.0, 101);  // cell 0.04
  const Boundary b = trace_zero_contour(circle, g);
  ASSERT_EQ(b.curves.size(), 1u);
  const Polyline& c = b.curves[0];
  EXPECT_EQ(c.front(), c.back());  // closed: the first point repeated
  EXPECT_GT(c.size(), 100u);
  // Linear interpolation of a quadratic along a cell edge of length h errs by <= h^2 / 4 here.
  for (const Eigen::Vector2d& p : c) EXPECT_NEAR(p.norm(), 1.0, 0.04 * 0.04 / 4.0);
  // Each point but the repeated one is distinct, and consecutive points are at most a cell
  // diagonal apart.
  for (std::size_t k = 0; k + 1 < c.size(); ++k) {
    EXPECT_GT((c[k + 1] - c[k]).norm(), 0.0);
    EXPECT_LE((c[k + 1] - c[k]).norm(), 0.04 * std::sqrt(2.0) + 1e-12);
  }
}

TEST(StudiesBoundary, ALinearFunctionIsTracedExactly) {
  PlaneGrid g;
  g.x1_min = 0.0;
  g.x1_max = 3.0;
  g.x2_min = -1.0;
  g.x2_max = 2.0;
  g.nodes = 31;
  const Boundary b =
      trace_zero_contour([](double x1, double x2) { return x2 - (0.3 * x1 + 0.1); }, g);
  ASSERT_EQ(b.curves.size(), 1u);
  const Polyline& c = b.curves[0];
  for (const Eigen::Vector2d& p : c) EXPECT_NEAR(p(1), 0.3 * p(0) + 0.1, 1e-12);
  // Open, from the rectangle's left side (the lower-numbered end) to its right side.
  EXPECT_NEAR(c.front()(0), 0.0, 1e-15);
  EXPECT_NEAR(c.back()(0), 3.0, 1e-15);
}

TEST(StudiesBoundary, LogAxisInterpolatesInLog10) {
  const PlaneGrid g{.x1_min = 100.0,
                    .x1_max = 5000.0,
                    .x2_min = 1e5,
                    .x2_max = 1e8,
                    .nodes = 21,
                    .scale2 = AxisScale::Log10};
  // Zero at Gdot = 10^(6.3 + 1e-4 G): linear in log10 Gdot, so exact on this grid.
  const Boundary b =
      trace_zero_contour([](double x1, double x2) { return std::log10(x2) - 6.3 - 1e-4 * x1; }, g);
  ASSERT_EQ(b.curves.size(), 1u);
  for (const Eigen::Vector2d& p : b.curves[0])
    EXPECT_NEAR(std::log10(p(1)), 6.3 + 1e-4 * p(0), 1e-12);
  EXPECT_NEAR(g.to_unit({100.0, 1e8})(1), 1.0, 1e-15);
  EXPECT_NEAR(g.to_unit({2550.0, std::pow(10.0, 6.5)})(0), 0.5, 1e-15);
  EXPECT_NEAR(g.to_unit({2550.0, std::pow(10.0, 6.5)})(1), 0.5, 1e-15);
}

TEST(StudiesBoundary, SaddleCellsKeepTheBranchesApart) {
  // x1 x2 = 1e-4: two hyperbola branches, in the first and third quadrants. With 40 nodes the
  // origin is a cell centre; that cell's corners alternate in sign (a saddle) and its centre
  // value -1e-4 says the branches pass on either side of it without joining.
  const Boundary b =
      trace_zero_contour([](double x1, double x2) { return x1 * x2 - 1e-4; }, square(1.0, 40));
  ASSERT_EQ(b.curves.size(), 2u);
  for (const Polyline& c : b.curves) {
    const double side = c.front()(0) > 0.0 ? 1.0 : -1.0;
    for (const Eigen::Vector2d& p : c) {
      EXPECT_GT(side * p(0), 0.0);
      EXPECT_GT(side * p(1), 0.0);
    }
  }
  // Ordered by their first grid edge: the third-quadrant branch starts on the bottom row.
  EXPECT_LT(b.curves[0].front()(1), 0.0);
  EXPECT_GT(b.curves[1].front()(1), 0.0);
}

TEST(StudiesBoundary, TracingIsDeterministicAndOrdersClosedCurves) {
  auto two_circles = [](double x1, double x2) {
    return std::min(std::hypot(x1 + 1.0, x2 - 0.5), std::hypot(x1 - 1.0, x2 + 0.5)) - 0.4;
  };
  const Boundary a = trace_zero_contour(two_circles, square(2.0, 81));
  const Boundary b = trace_zero_contour(two_circles, square(2.0, 81));
  ASSERT_EQ(a.curves.size(), 2u);
  ASSERT_EQ(b.curves.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) EXPECT_EQ(a.curves[k], b.curves[k]);
  // The circle about (1, -0.5) reaches the lower grid rows, so it comes first.
  EXPECT_GT(a.curves[0][0](0), 0.0);
  EXPECT_LT(a.curves[1][0](0), 0.0);
}

TEST(StudiesBoundary, NoCrossingGivesNoCurve) {
  EXPECT_TRUE(
      trace_zero_contour([](double, double) { return 1.0; }, square(1.0, 11)).curves.empty());
}

TEST(StudiesBoundary, RejectsBadGrids) {
  PlaneGrid g = square(1.0, 1);
  EXPECT_THROW(trace_zero_contour(circle, g), std::invalid_argument);
  g = square(1.0, 11);
  g.scale1 = AxisScale::Log10;  // x1 from -1
  EXPECT_THROW(trace_zero_contour(circle, g), std::invalid_argument);
  g = square(1.0, 11);
  EXPECT_THROW(trace_zero_contour(
                   [](double, double) { return std::numeric_limits<double>::quiet_NaN(); }, g),
               std::invalid_argument);
}

// The line x2 = x1 / 2 crosses the unit circle at +-(2, 1) / sqrt(5).
TEST(StudiesBoundary, LineAndCircleCrossAtTheAnalyticPoints) {
  const PlaneGrid g = square(2.0, 201);  // cell 0.02
  const Boundary circ = trace_zero_contour(circle, g);
  const Boundary line = trace_zero_contour([](double x1, double x2) { return x2 - 0.5 * x1; }, g);
  const std::vector<Intersection> hits = intersect_boundaries(line, circ);
  ASSERT_EQ(hits.size(), 2u);
  const Eigen::Vector2d p(2.0 / std::sqrt(5.0), 1.0 / std::sqrt(5.0));
  // Along the line from its left end: the lower-left point first.
  EXPECT_LT((hits[0].point + p).norm(), 2e-4);
  EXPECT_LT((hits[1].point - p).norm(), 2e-4);
  EXPECT_EQ(hits[0].curve_a, 0u);
  EXPECT_EQ(hits[0].curve_b, 0u);
  // The other way round gives the same points.
  EXPECT_EQ(intersect_boundaries(circ, line).size(), 2u);

  const auto near = nearest_intersection(hits, {1.0, 1.0}, g);
  ASSERT_TRUE(near.has_value());
  EXPECT_LT((near->point - p).norm(), 2e-4);
  EXPECT_EQ(first_intersection(hits)->point, hits[0].point);
  EXPECT_FALSE(first_intersection({}).has_value());
  EXPECT_FALSE(nearest_intersection({}, {0.0, 0.0}, g).has_value());
}

TEST(StudiesBoundary, PolylineCrossingsAreExactAndCountedOnceAtVertices) {
  const PlaneGrid frame = square(2.0, 2);
  // A closed unit square and its diagonal, which passes through two corners (shared vertices).
  const Polyline box = {{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}, {0.0, 0.0}};
  const Polyline diagonal = {{-0.5, -0.5}, {0.25, 0.25}, {1.5, 1.5}};
  std::vector<Intersection> hits = intersect_polylines({diagonal}, {box}, frame);
  ASSERT_EQ(hits.size(), 2u);
  EXPECT_EQ(hits[0].point, Eigen::Vector2d(0.0, 0.0));
  EXPECT_EQ(hits[1].point, Eigen::Vector2d(1.0, 1.0));
  // A horizontal line through the middle: exact points on the two sides.
  const Polyline mid = {{-1.0, 0.3}, {2.0, 0.3}};
  hits = intersect_polylines({mid}, {box}, frame);
  ASSERT_EQ(hits.size(), 2u);
  EXPECT_NEAR(hits[0].point(0), 0.0, 1e-15);
  EXPECT_NEAR(hits[0].point(1), 0.3, 1e-15);
  EXPECT_NEAR(hits[1].point(0), 1.0, 1e-15);
  EXPECT_EQ(hits[1].segment_b, 1u);
  // Parallel and disjoint curves do not cross.
  EXPECT_TRUE(intersect_polylines({{{0.0, 2.0}, {1.0, 2.0}}}, {box}, frame).empty());
}

// Hand-worked: the unit circle and the line x2 = 2 in the square [-4, 4]^2 come closest at
// (0, 1) and (0, 2), distance 1 = 1/8 of the square's side; the midpoint is (0, 1.5). A line
// through the circle gives distance 0 at a crossing.
TEST(StudiesBoundary, ClosestApproachOfDisjointAndCrossingCurves) {
  const PlaneGrid frame = square(4.0, 2);
  Polyline ring;
  for (int k = 0; k <= 720; ++k) {
    const double t = 2.0 * std::numbers::pi * k / 720.0;
    ring.push_back({std::sin(t), std::cos(t)});  // starts at the top, (0, 1), a vertex
  }
  const Polyline above = {{-3.0, 2.0}, {3.0, 2.0}};
  const auto c = closest_approach({above}, {ring}, frame);
  ASSERT_TRUE(c.has_value());
  EXPECT_NEAR(c->distance, 1.0 / 8.0, 1e-12);
  EXPECT_NEAR(c->on_a(0), 0.0, 1e-12);
  EXPECT_NEAR(c->on_a(1), 2.0, 1e-12);
  EXPECT_NEAR(c->on_b(1), 1.0, 1e-12);
  EXPECT_NEAR(c->midpoint(0), 0.0, 1e-12);
  EXPECT_NEAR(c->midpoint(1), 1.5, 1e-12);

  const Polyline through = {{-3.0, 0.5}, {3.0, 0.5}};
  const auto x = closest_approach({through}, {ring}, frame);
  ASSERT_TRUE(x.has_value());
  EXPECT_EQ(x->distance, 0.0);
  EXPECT_NEAR(std::abs(x->midpoint(0)), std::sqrt(0.75), 1e-4);  // a chord vertex is within
  EXPECT_NEAR(x->midpoint(1), 0.5, 1e-12);                       // 2 pi / 720 of the circle
  EXPECT_FALSE(closest_approach({}, {ring}, frame).has_value());
}

// In log10 plot coordinates the midpoint is the geometric mean.
TEST(StudiesBoundary, ClosestApproachMidpointIsTakenInPlotCoordinates) {
  const PlaneGrid frame{.x1_min = 1.0,
                        .x1_max = 1e4,
                        .x2_min = 1.0,
                        .x2_max = 1e4,
                        .scale1 = AxisScale::Log10,
                        .scale2 = AxisScale::Log10};
  const auto c =
      closest_approach({{{10.0, 1.0}, {10.0, 1e4}}}, {{{1000.0, 1.0}, {1000.0, 1e4}}}, frame);
  ASSERT_TRUE(c.has_value());
  EXPECT_NEAR(c->midpoint(0), 100.0, 1e-9);
  EXPECT_NEAR(c->distance, 0.5, 1e-12);  // 2 decades of 4
}

TEST(StudiesBoundary, WritesTheCurvesAsCsv) {
  Boundary b;
  b.curves = {{{0.0, 1.0}, {0.5, 1.5}}, {{2.0, 3.0}}};
  std::ostringstream out;
  write_boundary_csv(out, b);
  EXPECT_EQ(out.str(), "x1,x2,curve\n0,1,0\n0.5,1.5,0\n2,3,1\n");

  const std::filesystem::path path = testing::make_temp_dir("boundary") + "/boundary.csv";
  write_boundary_csv(path, b);
  EXPECT_EQ(testing::read_text(path), out.str());
}

}  // namespace
}  // namespace coldspray::studies
