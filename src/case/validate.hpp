// Checks that span several parts of a case (each part's own rules live in its schema).
#pragma once

#include "case/case.hpp"
#include "case/document.hpp"

namespace coldspray::case_file {

// InputError, located in `doc`, when: the contact normal names no body; a body's spacing
// exceeds the grid cell size; in axisymmetric geometry, a body is not symmetric about the z axis
// or moves off it.
void check_consistency(const Document& doc, const Case& c);

}  // namespace coldspray::case_file
