// Correspondence peridynamics against hand references: the families against a brute-force
// search; the patch test (a homogeneous deformation gives the exact F and Fdot at every point,
// PD paper eqs 5-6); the zero-energy-mode control (Silling 2017), whose rate resists a mode that
// leaves F unchanged and leaves a homogeneous deformation untouched, and which, accumulated over
// the steps, is Silling's penalty on the current positions; and the bond forces, whose sum over
// all points (weighted by volume) vanishes for any deformation.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/LU>
#include <cmath>
#include <string>
#include <vector>

#include "case/load.hpp"
#include "core/error.hpp"
#include "metrics/energy.hpp"
#include "pd/control_along_flow.hpp"
#include "pd/deformation.hpp"
#include "pd/forces.hpp"
#include "pd/setup.hpp"
#include "pd/stepper.hpp"
#include "pd/symmetry.hpp"
#include "pd/tensor_field.hpp"
#include "pd/time_step.hpp"

namespace coldspray::pd {
namespace {

// A block of elastic aluminium at 0.25 um spacing, 3 x 2.5 x 2 um unless given, with the extra
// body keys `more` (indented as keys of the body).
State block(const std::string& influence = "constant", const std::string& top = "2 um",
            const std::string& more = "") {
  const std::string text = R"(name: block
materials:
  elastic-al:
    density: 2700 kg/m^3
    elastic: {shear_modulus: 26 GPa, bulk_modulus: 66.4 GPa}
    strength: {model: elastic}
    eos: {model: linear}
    melt: {model: constant, temperature: 933 K}
    specific_heat: 896 J/kg/K
bodies:
  - name: block
    material: elastic-al
    shape: {type: box, min: [0, 0, 0], max: [3 um, 2.5 um, )" +
                           top + R"(]}
    spacing: 0.25 um
)" + more + R"(solver: {method: peridynamics, end_time: 1 ns}
peridynamics: {influence: )" +
                           influence + "}\n";
  return build_state(case_file::load_case_text("block.yaml", text, {}, {}));
}

TEST(PeridynamicFamilies, MatchABruteForceSearch) {
  const State s = block();
  const double h = 0.25e-6, delta = 3.0 * h;
  const std::size_t n = s.points.size();
  std::size_t bonds = 0;
  for (std::size_t i = 0; i < n; ++i) {
    std::size_t b = s.families.begin[i];
    for (std::size_t j = 0; j < n; ++j) {
      if (j == i) continue;
      double r2 = 0.0;
      for (int d = 0; d < 3; ++d)
        r2 += std::pow(s.neighbours.reference[j][d] - s.neighbours.reference[i][d], 2);
      const double beta = volume_fraction(std::sqrt(r2), delta, h);
      if (beta == 0.0) continue;
      ASSERT_LT(b, s.families.begin[i + 1]) << "point " << i;
      EXPECT_EQ(s.families.neighbour[b], j);
      // Stored to the nearest 2^-15 (pd/families.hpp).
      EXPECT_LE(std::abs(s.families.volume_fraction(b) - beta), 0.5 / 32768.0);
      ++b;
      ++bonds;
    }
    EXPECT_EQ(b, s.families.begin[i + 1]);
  }
  EXPECT_EQ(bonds, s.families.bonds());
  // An interior point has every lattice site within delta + h/2 = 3.5 h: 4/3 pi 3.5^3 = 180
  // sites, less the edge. Counted by hand over the integer lattice: 178 sites with
  // i^2 + j^2 + k^2 <= 12.25 besides the origin (|xi| = 3.5 h itself has none).
  std::size_t most = 0;
  for (std::size_t i = 0; i < n; ++i)
    most = std::max<std::size_t>(most, s.families.begin[i + 1] - s.families.begin[i]);
  EXPECT_EQ(most, 178u);
}

// One layer of points: every family is flat, its shape tensor singular (eq 6), and the set-up
// says so, naming the body's spacing.
TEST(PeridynamicFamilies, AFlatBodyIsAnInputError) {
  try {
    block("constant", "0.25 um");
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "bodies.block.spacing");
    EXPECT_NE(std::string(e.message()).find("does not span three dimensions"), std::string::npos);
  }
}

TEST(PeridynamicFamilies, PartialVolumeAcrossTheHorizonEdge) {
  const double h = 1.0, delta = 3.0;
  EXPECT_DOUBLE_EQ(volume_fraction(2.5, delta, h), 1.0);
  EXPECT_DOUBLE_EQ(volume_fraction(3.0, delta, h), 0.5);
  EXPECT_DOUBLE_EQ(volume_fraction(3.25, delta, h), 0.25);
  EXPECT_DOUBLE_EQ(volume_fraction(3.5, delta, h), 0.0);
}

// y = F0 X + c and v = L0 y at every point.
void deform(State& s, const Eigen::Matrix3d& F0, const Eigen::Matrix3d& L0) {
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    const Eigen::Vector3d y =
        F0 * s.neighbours.reference[i].head<3>() + Eigen::Vector3d(1e-7, -2e-7, 3e-7);
    const Eigen::Vector3d v = L0 * y;
    for (int d = 0; d < 3; ++d) {
      s.points.position[d][i] = y[d];
      s.points.velocity[d][i] = v[d];
    }
  }
  refresh_neighbours(s);
}

TEST(PeridynamicKinematics, HomogeneousDeformationGivesTheExactGradientAtEveryPoint) {
  Eigen::Matrix3d F0, L0;
  F0 << 1.10, 0.05, -0.02, 0.03, 0.95, 0.04, -0.01, 0.02, 1.07;
  L0 << 2e6, -1e6, 3e5, 4e5, -1e6, 2e5, -3e5, 1e5, 5e5;
  for (const std::string influence : {"constant", "inverse_distance"}) {
    State s = block(influence);
    deform(s, F0, L0);
    double worst_F = 0.0, worst_Fdot = 0.0;
    for (std::size_t i = 0; i < s.points.size(); ++i) {
      const Deformation d = deformation(s.families, s.neighbours, bond_weights(s, 0),
                                        tensor_at(s.shape_inverse, i), s.moment_inverse[i], i);
      worst_F = std::max(worst_F, (d.F - F0).cwiseAbs().maxCoeff());
      worst_Fdot = std::max(worst_Fdot, (d.Fdot - L0 * F0).cwiseAbs().maxCoeff() / 2e6);
    }
    EXPECT_LT(worst_F, 1e-12) << influence;
    EXPECT_LT(worst_Fdot, 1e-12) << influence;
  }
}

// Sets every point's F and the second-order fit of its velocities from its family, and
// A = P K^-1 from a given uniform Cauchy stress.
void set_gradients(State& s, const Eigen::Matrix3d& sigma) {
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    const Deformation d = deformation(s.families, s.neighbours, bond_weights(s, 0),
                                      tensor_at(s.shape_inverse, i), s.moment_inverse[i], i);
    store_tensor(d.F, s.deformation_gradient, i);
    s.velocity_fit[i] = d.velocity_fit;
    const Eigen::Matrix3d A =
        d.F.determinant() * sigma * d.F.inverse().transpose() * tensor_at(s.shape_inverse, i);
    store_tensor(A, s.piola_over_shape, i);
  }
}

// Interior points: a horizon away from every face.
bool interior(const State& s, std::size_t i) {
  const double delta = s.body_bonds[0].horizon, max[3] = {3e-6, 2.5e-6, 2e-6};
  for (int d = 0; d < 3; ++d) {
    const double x = s.neighbours.reference[i][d];
    if (x < delta + 1e-9 || x > max[d] - delta - 1e-9) return false;
  }
  return true;
}

TEST(PeridynamicControl, ResistsAZeroEnergyModeAndLeavesHomogeneousDeformationAlone) {
  State s = block();
  const double h = 0.25e-6, amplitude = 1.0;
  // v = a (-1)^(i+j+k) e_x on the lattice: xi and -xi see the same difference, so the sums of
  // eq 5 cancel and Fdot = 0 at interior points, a motion the correspondence force cannot see.
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    long parity = 0;
    for (int d = 0; d < 3; ++d) parity += std::lround(s.neighbours.reference[i][d] / h - 0.5);
    s.points.velocity[0][i] = (parity % 2 == 0 ? 1.0 : -1.0) * amplitude;
  }
  refresh_neighbours(s);
  std::size_t checked = 0;
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    if (!interior(s, i)) continue;
    ++checked;
    const Deformation d = deformation(s.families, s.neighbours, bond_weights(s, 0),
                                      tensor_at(s.shape_inverse, i), s.moment_inverse[i], i);
    EXPECT_LT(d.Fdot.norm(), 1e-12 * amplitude / h);
  }
  set_gradients(s, Eigen::Matrix3d::Zero());
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    if (!interior(s, i)) continue;
    const ForceDensity f = force_density(s, i);
    EXPECT_EQ(f.bonds.norm(), 0.0);
    EXPECT_LT(f.control_rate[0] * s.points.velocity[0][i], 0.0)
        << "point " << i << ": the control must resist";
  }
  EXPECT_GT(checked, 20u);

  // A homogeneous velocity gradient: zdot = (v_j - v_i) - Fdot xi = 0 on every bond, so no
  // control anywhere, surface points included.
  State t = block();
  Eigen::Matrix3d L0;
  L0 << 1e6, 2e6, 0.0, 0.0, -1e6, 1e6, 0.0, 0.0, 5e5;
  deform(t, Eigen::Matrix3d::Identity(), L0);
  set_gradients(t, Eigen::Matrix3d::Zero());
  double worst = 0.0;
  for (std::size_t i = 0; i < t.points.size(); ++i)
    worst = std::max(worst, force_density(t, i).control_rate.norm());
  // The scale: the control's rate on the zero-energy mode above, per unit of velocity.
  const double unit = s.settings.stabilization * s.body_bonds[0].micromodulus * 1e-6;
  EXPECT_LT(worst, 1e-10 * unit);
}

// A smooth non-uniform motion, v = u(X) / (1 s) with u quadratic in X: the second-order fit
// reproduces every bond exactly, so the control's rate is zero at every point, surface points
// included. Measured against the linear map of eq 5 instead (Silling's zdot = (v_j - v_i) -
// Fdot xi), the truncated families of the surface points see the curvature as non-uniformity:
// that is the force the second-order reference removes (docs/pd.md, "Zero-energy modes").
TEST(PeridynamicControl, LeavesAQuadraticDeformationAloneAtSurfacesToo) {
  State s = block();
  const double strain = 1e-3, L = 2e-6;
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    const Eigen::Vector3d X = s.neighbours.reference[i].head<3>();
    const Eigen::Vector3d u(X[0] * X[0] - 0.5 * X[1] * X[2], X[1] * X[0] + X[2] * X[2],
                            0.3 * X[0] * X[2] - X[1] * X[1]);
    for (int d = 0; d < 3; ++d) s.points.velocity[d][i] = strain / L * u[d];
  }
  refresh_neighbours(s);
  set_gradients(s, Eigen::Matrix3d::Zero());
  double worst_fit = 0.0, worst = 0.0, linear_surface = 0.0;
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    for_each_bond(s.families, s.neighbours, bond_weights(s, 0), i,
                  [&](std::size_t, std::size_t j, const Eigen::Vector3d& xi, double, double) {
                    const Eigen::Vector3d V =
                        (s.neighbours.velocity[j] - s.neighbours.velocity[i]).head<3>();
                    const Eigen::Vector3d zdot =
                        V - (s.velocity_fit[i] * monomials(xi, s.body_bonds[0].horizon)).head<3>();
                    worst_fit = std::max(worst_fit, zdot.norm() / V.norm());
                  });
    worst = std::max(worst, force_density(s, i).control_rate.norm());
  }
  // The same field against the linear reference: Cdot = [delta Fdot, 0].
  State t = s;
  for (std::size_t i = 0; i < t.points.size(); ++i) {
    const Deformation d = deformation(t.families, t.neighbours, bond_weights(t, 0),
                                      tensor_at(t.shape_inverse, i), t.moment_inverse[i], i);
    t.velocity_fit[i].setZero();
    t.velocity_fit[i].topLeftCorner<3, 3>() = t.body_bonds[0].horizon * d.Fdot;
  }
  for (std::size_t i = 0; i < t.points.size(); ++i)
    if (!interior(t, i))
      linear_surface = std::max(linear_surface, force_density(t, i).control_rate.norm());
  EXPECT_LT(worst_fit, 1e-10);
  EXPECT_GT(linear_surface, 0.0);
  EXPECT_LT(worst, 1e-8 * linear_surface);
}

// The control's force is accumulated from its rate step by step (pd/forces.hpp). In an elastic
// body (r = 1) the sum is Silling's penalty G_s c / l omega (z_i + z_j) on the current
// positions, z = Y - C q(xi), because z is linear in the positions and velocity Verlet moves
// them by dt v^{n+1/2}, the velocities the rate is taken with. The penalty on the positions is
// the same force function with the positions in place of the velocities (C is then the
// positions' fit): the reference here.
TEST(PeridynamicControl, AccumulatesToSillingsPenaltyOnThePositions) {
  State s = block();
  for (std::size_t i = 0; i < s.points.size(); ++i)
    for (int d = 0; d < 3; ++d) s.points.velocity[d][i] = 2.0 * std::sin(1.3 * i + 2.1 * d);
  for (int k = 0; k < 40; ++k) {
    s.dt = stable_time_step(s, 0.6);
    step(s);
  }
  State t = s;
  for (std::size_t i = 0; i < t.points.size(); ++i)
    for (int d = 0; d < 3; ++d) t.points.velocity[d][i] = t.points.position[d][i];
  refresh_neighbours(t);
  set_gradients(t, Eigen::Matrix3d::Zero());
  double worst = 0.0, largest = 0.0;
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    EXPECT_EQ(s.flow_softening[i], 0.0);  // the elastic control
    const Eigen::Vector3d penalty = force_density(t, i).control_rate;
    worst = std::max(worst, (vector_at(s.control_force, i) - penalty).norm());
    largest = std::max(largest, penalty.norm());
  }
  EXPECT_GT(largest, 0.0);
  EXPECT_LT(worst, 1e-9 * largest);  // measured 1.0e-11 (40 steps)
}

// The penalty is a linear function of the displacements (above), f = -A u; it derives from a
// stored energy, and so can only give back what it took, if and only if A is symmetric in the
// points' volumes: the work of one field's force on another's displacement equals the converse
// (Betti's reciprocity), sum V_i w_i . f(u)_i = sum V_i u_i . f(w)_i, for any two fields.
TEST(PeridynamicControl, IsConservative) {
  State s = block();
  const auto control_of = [&](auto field) {
    std::vector<Eigen::Vector3d> f(s.points.size());
    for (std::size_t i = 0; i < s.points.size(); ++i)
      for (int d = 0; d < 3; ++d) s.points.velocity[d][i] = field(i, d);
    refresh_neighbours(s);
    set_gradients(s, Eigen::Matrix3d::Zero());
    for (std::size_t i = 0; i < s.points.size(); ++i) f[i] = force_density(s, i).control_rate;
    return f;
  };
  const auto u = [](std::size_t i, int d) { return std::sin(1.3 * i + 2.1 * d); };
  const auto w = [](std::size_t i, int d) { return std::cos(0.7 * i - 1.1 * d + 0.3); };
  const std::vector<Eigen::Vector3d> f_u = control_of(u), f_w = control_of(w);
  double w_on_u = 0.0, u_on_w = 0.0, scale = 0.0;
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    const double V = s.points.volume0[i];
    const Eigen::Vector3d u_i(u(i, 0), u(i, 1), u(i, 2)), w_i(w(i, 0), w(i, 1), w(i, 2));
    w_on_u += V * w_i.dot(f_u[i]);
    u_on_w += V * u_i.dot(f_w[i]);
    scale += V * w_i.norm() * f_u[i].norm();
  }
  EXPECT_LT(std::abs(w_on_u - u_on_w), 1e-12 * scale) << w_on_u << " against " << u_on_w;
}

TEST(PeridynamicForces, InternalForcesSumToZero) {
  State s = block();
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    for (int d = 0; d < 3; ++d) {
      s.points.position[d][i] += 1e-9 * std::sin(1.7 * i + 0.9 * d);
      s.points.velocity[d][i] = std::cos(0.7 * i + 1.3 * d);
    }
    // Unequal ends: softened along flow directions that differ from point to point.
    s.flow_softening[i] = 0.5 + 0.5 * std::sin(0.3 * i);
    Eigen::Matrix3d sigma_i;
    sigma_i << std::sin(0.4 * i), 1.0, 0.3, 1.0, std::cos(0.9 * i), -0.5, 0.3, -0.5, 0.2;
    store_tensor(flow_direction(sigma_i), s.flow_direction, i);
  }
  refresh_neighbours(s);
  Eigen::Matrix3d sigma;
  sigma << 1e8, 2e7, 0.0, 2e7, -5e7, 1e7, 0.0, 1e7, 3e7;
  set_gradients(s, sigma);
  Eigen::Vector3d bonds = Eigen::Vector3d::Zero(), bond_scale = Eigen::Vector3d::Zero();
  Eigen::Vector3d control = Eigen::Vector3d::Zero(), control_scale = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    const ForceDensity f = force_density(s, i);
    bonds += f.bonds * s.points.volume0[i];
    bond_scale += f.bonds.cwiseAbs() * s.points.volume0[i];
    control += f.control_rate * s.points.volume0[i];
    control_scale += f.control_rate.cwiseAbs() * s.points.volume0[i];
  }
  EXPECT_LT(bonds.norm(), 1e-12 * bond_scale.norm());
  EXPECT_LT(control.norm(), 1e-12 * control_scale.norm());
}

// A block moving down at 10 m/s whose bottom face is held from t = 0: the hold takes the
// bottom layer's kinetic energy, 1/2 m v^2 summed over its 12 x 10 points, into the budget's
// contact entry, and the budget stays closed to a small part of it.
TEST(PeridynamicHolds, TheKineticEnergyAHoldTakesIsBooked) {
  State s = block("constant", "2 um", "    velocity: [0, 0, -10 m/s]\n    fixed: [bottom]\n");
  const metrics::EnergyBudget before = metrics::energy_budget(s);
  double held_kinetic = 0.0;
  std::size_t held = 0;
  for (std::size_t i = 0; i < s.points.size(); ++i)
    if (s.held[i] == 0b111) {
      ++held;
      held_kinetic += 0.5 * s.points.mass[i] * 100.0;
    }
  EXPECT_EQ(held, 12u * 10u);
  for (int k = 0; k < 5; ++k) {
    s.dt = stable_time_step(s, 0.3);
    step(s);
  }
  const metrics::EnergyBudget after = metrics::energy_budget(s);
  EXPECT_NEAR(after.contact, held_kinetic, 1e-12 * held_kinetic);
  // Unbooked, the budget would be off by the whole held_kinetic; what remains (3 % of it) is
  // the time integration's error after the sudden stop.
  EXPECT_NEAR(after.total(), before.total(), 0.1 * held_kinetic);
}

// The smallest principal stretch, whatever the rotations around it; a stretched point counts
// at 1 (pd/time_step.hpp).
TEST(PeridynamicTimeStep, TheCompressedStretchIsTheSmallestPrincipalOne) {
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).matrix();
  const Eigen::Matrix3d Q =
      Eigen::AngleAxisd(-1.1, Eigen::Vector3d(3, -1, 2).normalized()).matrix();
  EXPECT_NEAR(compressed_stretch(R * Eigen::Vector3d(0.2, 1.5, 3.0).asDiagonal() * Q.transpose()),
              0.2, 1e-12);
  EXPECT_NEAR(compressed_stretch(R * Eigen::Vector3d(2.4, 0.13, 3.1).asDiagonal()), 0.13, 1e-12);
  EXPECT_EQ(compressed_stretch(Eigen::Vector3d(1.2, 1.1, 1.3).asDiagonal() * Q), 1.0);
  EXPECT_EQ(compressed_stretch(Eigen::Matrix3d::Identity()), 1.0);
  // Nearly undeformed: Weyl's lower bound, no more than 2.5 % short. Here C - I has eigenvalues
  // 0.999^2 - 1, 1.002^2 - 1 and 0, so the bound is sqrt(1 - |C - I|_F).
  const double near = compressed_stretch(R * Eigen::Vector3d(0.999, 1.002, 1.0).asDiagonal() * Q);
  const double distance = std::hypot(0.999 * 0.999 - 1.0, 1.002 * 1.002 - 1.0);
  EXPECT_NEAR(near, std::sqrt(1.0 - distance), 1e-12);
  EXPECT_LT(near, 0.999);
  EXPECT_GT(near, 0.975 * 0.999);
}

// A block at rest, deformed homogeneously to principal stretches 0.5, 2 and 1 (J = 1, so its
// density and wave speed c = sqrt((K + 4G/3) / rho) = 6118.3 m/s are those at rest): after a
// step, the time step is cfl h / c times min(1, 0.5 / 0.7), the factor by which compression to
// the stretch 0.5 lowers the stable step (docs/pd.md, "Time step").
TEST(PeridynamicTimeStep, FollowsTheSmallestStretchOfTheDeformation) {
  State s = block();
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, -1, 2).normalized()).matrix();
  deform(s, R * Eigen::Vector3d(0.5, 2.0, 1.0).asDiagonal(), Eigen::Matrix3d::Zero());
  const double c = std::sqrt((66.4e9 + 4.0 / 3.0 * 26e9) / 2700.0);
  EXPECT_NEAR(stable_time_step(s, 1.2), 1.2 * 0.25e-6 / c, 1e-12 * 0.25e-6 / c);  // at rest
  s.dt = 1e-15;
  step(s);
  for (std::size_t i = 0; i < s.points.size(); ++i)
    ASSERT_NEAR(s.compressed_stretch[i], 0.5, 1e-12) << "point " << i;
  EXPECT_NEAR(stable_time_step(s, 1.2), 1.2 * (0.5 / 0.7) * 0.25e-6 / c, 1e-9 * 0.25e-6 / c);
}

// A point crushed to a stretch below 0.01 stops the run with its name, rather than stalling it
// on a step a hundredth of the undeformed one.
TEST(PeridynamicTimeStep, ACrushedPointIsAFault) {
  State s = block();
  deform(s, Eigen::Vector3d(1.0, 0.009, 1.0).asDiagonal(), Eigen::Matrix3d::Zero());
  s.dt = 1e-15;
  try {
    step(s);
    FAIL() << "no fault";
  } catch (const RunFault& e) {
    EXPECT_NE(std::string(e.what()).find("smallest principal stretch of F is below 0.01"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace coldspray::pd
