// The material update of a body's points in batches (bodies/update_points.hpp) and the move of a
// point's state between the arrays and materials::PointState (bodies/material_state.hpp), by
// hand: an elastic shear gives sigma_xy = 2 G eps_xy at each point from its own kinematics, the
// short last batch writes only the body's points, and the largest c + |v| comes back.
#include "bodies/update_points.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "elastic_case.hpp"

namespace coldspray::bodies {
namespace {

using testing::box;
using testing::elastic_case;
using testing::kPWave;

TEST(MaterialState, AStateStoredIsTheStateLoadedComponentByComponent) {
  materials::PointState in;
  for (int c = 0; c < 6; ++c) in.stress.c[c] = 1e6 * (c + 1);
  in.eqps = 0.1, in.eqps_rate = 2e6, in.return_slope = 3e9, in.temperature = 450.0;
  in.energy = 5e7, in.J = 0.98, in.flow_stress = 2e8, in.shear_modulus = 2.5e10;
  Points P;
  P.resize(3);
  store_point_state(in, P, 1);
  // The arrays name the components as the tensor does: xy is (0, 1), yz (1, 2), xz (0, 2).
  EXPECT_EQ(P.stress[kXY][1], in.stress(0, 1));
  EXPECT_EQ(P.stress[kYZ][1], in.stress(2, 1));
  EXPECT_EQ(P.stress[kXZ][1], in.stress(2, 0));
  EXPECT_EQ(P.stress[kZZ][1], 3e6);
  EXPECT_EQ(P.temperature[0], 0.0);  // the neighbours untouched
  EXPECT_EQ(P.temperature[2], 0.0);
  const materials::PointState out = load_point_state(P, 1);
  EXPECT_EQ(out.stress, in.stress);
  EXPECT_EQ(out.eqps, in.eqps);
  EXPECT_EQ(out.eqps_rate, in.eqps_rate);
  EXPECT_EQ(out.return_slope, in.return_slope);
  EXPECT_EQ(out.temperature, in.temperature);
  EXPECT_EQ(out.energy, in.energy);
  EXPECT_EQ(out.J, in.J);
  EXPECT_EQ(out.flow_stress, in.flow_stress);
  EXPECT_EQ(out.shear_modulus, in.shear_modulus);
}

TEST(UpdatePoints, ABodyIsCutIntoBatchesOfFourPoints) {
  BodyRange body;
  for (const auto& [points, batches] : {std::pair{0, 0}, {1, 1}, {4, 1}, {6, 2}, {8, 2}, {9, 3}}) {
    body.begin = 5, body.end = 5 + points;
    EXPECT_EQ(batch_count(body), static_cast<std::size_t>(batches)) << points << " points";
  }
}

TEST(UpdatePoints, EachPointOfTheBodyIsUpdatedWithItsOwnKinematicsAndNoOtherIs) {
  const case_file::Case c = elastic_case(box("block", "[0, 0, 0]", "[1 um, 1 um, 1 um]"));
  const materials::Material& m = c.materials.at("elastic-al");
  // Points 1-6 are the body's (two batches, the second of two points); 0 and 7 another's.
  Points P;
  P.resize(8);
  for (std::size_t p = 0; p < 8; ++p) {
    store_point_state(materials::initial_state(m, 298.0), P, p);
    P.sound_speed[p] = -1.0;
  }
  P.velocity[1][5] = -300.0;
  P.velocity[1][7] = -5000.0;  // not the body's: not in its largest speed
  BodyRange body;
  body.begin = 1, body.end = 7, body.material = m;
  std::vector<std::size_t> completed;
  const double max_speed = materials::visit_models(m, [&](const auto& models) {
    return update_batches(
        models, P, body, 0, batch_count(body),
        [](std::size_t p) {
          materials::StepKinematics k;
          k.strain_increment(0, 1) = 1e-5 * static_cast<double>(p);  // a shear without volume
          k.dt = 1e-9;
          return k;
        },
        [&](std::size_t p, const materials::StepKinematics&, const materials::PointState& st) {
          completed.push_back(p);
          store_point_state(st, P, p);
        });
  });
  EXPECT_EQ(completed, (std::vector<std::size_t>{1, 2, 3, 4, 5, 6}));
  for (std::size_t p = 1; p < 7; ++p) {
    // 2 x 26 GPa x p 1e-5 = p 0.52 MPa; no pressure at J = 1 (linear EOS), no other component.
    EXPECT_NEAR(P.stress[kXY][p], 5.2e5 * static_cast<double>(p), 1e-3) << "point " << p;
    EXPECT_NEAR(P.stress[kXX][p], 0.0, 1e-6);
    EXPECT_NEAR(P.stress[kZZ][p], 0.0, 1e-6);
    EXPECT_NEAR(P.sound_speed[p], kPWave, 1e-3);
  }
  for (const std::size_t p : {0u, 7u}) {
    EXPECT_EQ(P.stress[kXY][p], 0.0);
    EXPECT_EQ(P.sound_speed[p], -1.0);
  }
  EXPECT_NEAR(max_speed, kPWave + 300.0, 1e-3);
}

}  // namespace
}  // namespace coldspray::bodies
