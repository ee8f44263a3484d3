#include "case/validate.hpp"

#include <cmath>
#include <string>
#include <vector>

#include "case/shortest_number.hpp"
#include "case/suggest.hpp"
#include "core/error.hpp"

namespace coldspray::case_file {

namespace {

void check_contact_body(const Document& doc, const Case& c) {
  if (c.contact.mpm.normal != ContactNormal::Body) {
    if (c.contact.mpm.other_pairs_normal != ContactNormal::MaxGradient)
      fail_at(doc, {"contact", "mpm", "other_pairs_normal"},
              "applies with contact.mpm.normal: body:NAME only (the pairs without that body)");
    return;
  }
  std::vector<std::string_view> names;
  for (const Body& b : c.bodies) {
    if (b.name == c.contact.mpm.normal_body) return;
    names.push_back(b.name);
  }
  fail_at(doc, {"contact", "mpm", "normal"},
          unknown_word("body", c.contact.mpm.normal_body, names));
}

void check_grip_body(const Document& doc, const Case& c) {
  if (!c.grip) return;
  std::vector<std::string_view> names;
  for (const Body& b : c.bodies) {
    if (b.name == c.grip->body) return;
    names.push_back(b.name);
  }
  fail_at(doc, {"grip", "body"}, unknown_word("body", c.grip->body, names));
}

void check_spacing(const Document& doc, const Grid& grid, const Body& b) {
  if (b.spacing > grid.cell_size)
    fail_at(doc, {"bodies", b.name, "spacing"},
            "must not exceed grid.cell_size (" + shortest_text(b.spacing) + " m > " +
                shortest_text(grid.cell_size) + " m)");
  // The coarsest points too: a point larger than a cell would skip nodes (GIMP's support).
  if (b.coarsening && std::ldexp(b.spacing, b.coarsening->levels) > grid.cell_size * (1 + 1e-12))
    fail_at(doc, {"bodies", b.name, "coarsening", "levels"},
            "makes points of " + shortest_text(std::ldexp(b.spacing, b.coarsening->levels)) +
                " m, larger than grid.cell_size (" + shortest_text(grid.cell_size) +
                " m): at most spacing x 2^levels = cell_size");
}

// The MPM needs its grid; PD runs in 3D (its families and contact are three-dimensional).
void check_solver_sections(const Document& doc, const Case& c) {
  switch (c.solver.method) {
    case Method::Mpm:
      if (!c.grid)
        fail_at(doc, {"grid"}, "missing: solver.method mpm needs a grid (grid.cell_size)");
      if (c.symmetry)
        fail_at(doc, {"symmetry"},
                "is peridynamics only: with solver.method mpm, the symmetry planes are the grid's "
                "roller faces (grid.faces)");
      for (const Body& b : c.bodies)
        if (!b.roller.empty())
          fail_at(doc, {"bodies", b.name, "roller"},
                  "is peridynamics only: with solver.method mpm, hold a plane with grid.faces");
      if (c.contact.peridynamics.model != ContactModel::Repulsive)
        fail_at(doc, {"contact", "peridynamics", "model"},
                "is peridynamics only: the MPM's grid contact has no force law to choose");
      if (c.solver.cfl > kMaxMpmCfl)
        fail_at(doc, {"solver", "cfl"},
                "must be in (0, 1] with solver.method mpm, got '" + shortest_text(c.solver.cfl) +
                    "' (the explicit MPM's bound is 1)");
      return;
    case Method::Peridynamics:
      if (c.solver.geometry != Geometry::ThreeD)
        fail_at(doc, {"solver", "geometry"},
                "must be 3d with solver.method peridynamics (axisymmetric is MPM only)");
      if (c.bonding.model != BondingModel::None)
        fail_at(doc, {"bonding", "model"},
                "must be none with solver.method peridynamics (the direct bonding model is MPM's)");
      for (const Body& b : c.bodies)
        if (b.coarsening)
          fail_at(doc, {"bodies", b.name, "coarsening"},
                  "is MPM only: peridynamic families need one spacing");
      return;
  }
}

bool on_z_axis(const Vec3& v) { return v.x() == 0.0 && v.y() == 0.0; }

void check_axisymmetric(const Document& doc, const Body& b) {
  if (std::holds_alternative<geometry::Box>(b.shape)) {
    fail_at(doc, {"bodies", b.name, "shape", "type"},
            "a box is not symmetric about the z axis; axisymmetric geometry takes spheres and "
            "cylinders");
  }
  if (const auto* s = std::get_if<geometry::Sphere>(&b.shape); s && !on_z_axis(s->center)) {
    fail_at(doc, {"bodies", b.name, "shape", "center"},
            "must lie on the z axis (x = y = 0) in axisymmetric geometry");
  }
  if (const auto* cyl = std::get_if<geometry::Cylinder>(&b.shape);
      cyl && !on_z_axis(cyl->base_center)) {
    fail_at(doc, {"bodies", b.name, "shape", "base_center"},
            "must lie on the z axis (x = y = 0) in axisymmetric geometry");
  }
  if (!on_z_axis(b.velocity)) {
    fail_at(doc, {"bodies", b.name, "velocity"},
            "must be along z (x = y = 0) in axisymmetric geometry");
  }
}

}  // namespace

void check_consistency(const Document& doc, const Case& c) {
  check_contact_body(doc, c);
  check_grip_body(doc, c);
  check_solver_sections(doc, c);
  if (c.solver.geometry == Geometry::ThreeD && c.grid && c.grid->min && c.grid->max &&
      (*c.grid->min)[1] >= (*c.grid->max)[1])
    fail_at(doc, {"grid", "max"}, "must be greater than min in y in 3D geometry");
  for (const Body& b : c.bodies) {
    if (c.solver.method == Method::Mpm) check_spacing(doc, *c.grid, b);
    if (c.solver.geometry == Geometry::Axisymmetric) check_axisymmetric(doc, b);
  }
}

}  // namespace coldspray::case_file
