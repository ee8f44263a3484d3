// Units the tests write their lengths in.
#pragma once

namespace coldspray::testing {

inline constexpr double um = 1e-6;  // a micrometre, m

}  // namespace coldspray::testing
