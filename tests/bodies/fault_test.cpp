// A fault found in a step (bodies/bodies.hpp, describe_point.hpp): the lowest point at fault is
// the one reported, whatever the order the threads found them in, and the report names its body,
// its index at t = 0, where it is and when.
#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "bodies/bodies.hpp"
#include "bodies/describe_point.hpp"
#include "core/error.hpp"

namespace coldspray::bodies {
namespace {

// Two bodies of two points; the substrate's second point (index 3) was point 7 at t = 0.
Bodies renumbered_pair() {
  Bodies s;
  s.points.resize(4);
  const std::uint32_t ids[] = {0, 1, 6, 7};
  for (std::size_t p = 0; p < 4; ++p) s.points.id[p] = ids[p];
  s.points.position[0][3] = 1.5e-6;
  s.points.position[1][3] = -0.25e-6;
  s.points.position[2][3] = 12e-6;
  BodyRange particle, substrate;
  particle.name = "particle", particle.begin = 0, particle.end = 2;
  substrate.name = "substrate", substrate.begin = 2, substrate.end = 4;
  s.bodies = {particle, substrate};
  s.time = 2.5e-9;
  return s;
}

TEST(Fault, TheLowestPointAtFaultIsKeptWhateverTheOrder) {
  Fault f;
  EXPECT_EQ(f.point, std::numeric_limits<std::size_t>::max());
  record_fault(f, 3, "a non-finite stress");
  record_fault(f, 5, "a crushed point");
  EXPECT_EQ(f.point, 3u);
  EXPECT_STREQ(f.cause, "a non-finite stress");
  record_fault(f, 1, "a crushed point");
  EXPECT_EQ(f.point, 1u);
  EXPECT_STREQ(f.cause, "a crushed point");
}

TEST(Fault, APointIsNamedByItsBodyItsIndexAtTheStartWhereItIsAndWhen) {
  EXPECT_EQ(describe_point(renumbered_pair(), 3),
            "body 'substrate', point 7 at (1.5, -0.25, 12) um, t = 2.5 ns");
}

TEST(Fault, ARecordedFaultIsRaisedAsARunFaultAndNoneIsNot) {
  Bodies s = renumbered_pair();
  EXPECT_NO_THROW(raise_recorded_fault(s));
  record_fault(s.fault, 3, "its stress is not finite");
  try {
    raise_recorded_fault(s);
    FAIL() << "no RunFault";
  } catch (const RunFault& e) {
    EXPECT_EQ(std::string(e.what()),
              "body 'substrate', point 7 at (1.5, -0.25, 12) um, t = 2.5 ns: its stress is not "
              "finite");
  }
}

}  // namespace
}  // namespace coldspray::bodies
