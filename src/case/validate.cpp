#include "case/validate.hpp"

#include <string>
#include <vector>

#include "case/shortest_number.hpp"
#include "case/suggest.hpp"
#include "core/error.hpp"

namespace coldspray::case_file {

namespace {

[[noreturn]] void fail(const Document& doc, const std::vector<std::string>& path,
                       const std::string& message) {
  std::string key;
  for (const std::string& segment : path) key += (key.empty() ? "" : ".") + segment;
  throw InputError(doc.where(path), key, message);
}

void check_contact_body(const Document& doc, const Case& c) {
  if (c.contact.normal != ContactNormal::Body) return;
  std::vector<std::string_view> names;
  for (const Body& b : c.bodies) {
    if (b.name == c.contact.normal_body) return;
    names.push_back(b.name);
  }
  fail(doc, {"contact", "normal"}, unknown_word("body", c.contact.normal_body, names));
}

void check_spacing(const Document& doc, const Case& c, const Body& b) {
  if (b.spacing <= c.grid.cell_size) return;
  fail(doc, {"bodies", b.name, "spacing"},
       "must not exceed grid.cell_size (" + shortest_text(b.spacing) + " m > " +
           shortest_text(c.grid.cell_size) + " m)");
}

bool on_z_axis(const Vec3& v) { return v.x() == 0.0 && v.y() == 0.0; }

void check_axisymmetric(const Document& doc, const Body& b) {
  if (std::holds_alternative<Box>(b.shape)) {
    fail(doc, {"bodies", b.name, "shape", "type"},
         "a box is not symmetric about the z axis; axisymmetric geometry takes spheres and "
         "cylinders");
  }
  if (const auto* s = std::get_if<Sphere>(&b.shape); s && !on_z_axis(s->center)) {
    fail(doc, {"bodies", b.name, "shape", "center"},
         "must lie on the z axis (x = y = 0) in axisymmetric geometry");
  }
  if (const auto* cyl = std::get_if<Cylinder>(&b.shape); cyl && !on_z_axis(cyl->base_center)) {
    fail(doc, {"bodies", b.name, "shape", "base_center"},
         "must lie on the z axis (x = y = 0) in axisymmetric geometry");
  }
  if (!on_z_axis(b.velocity)) {
    fail(doc, {"bodies", b.name, "velocity"},
         "must be along z (x = y = 0) in axisymmetric geometry");
  }
}

}  // namespace

void check_consistency(const Document& doc, const Case& c) {
  check_contact_body(doc, c);
  if (c.solver.geometry == Geometry::ThreeD && c.grid.min && c.grid.max &&
      (*c.grid.min)[1] >= (*c.grid.max)[1])
    fail(doc, {"grid", "max"}, "must be greater than min in y in 3D geometry");
  for (const Body& b : c.bodies) {
    check_spacing(doc, c, b);
    if (c.solver.geometry == Geometry::Axisymmetric) check_axisymmetric(doc, b);
  }
}

}  // namespace coldspray::case_file
