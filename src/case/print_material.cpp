#include <fmt/format.h>

#include <algorithm>
#include <ostream>

#include "case/load.hpp"
#include "case/material_schema.hpp"
#include "case/shortest_number.hpp"

namespace coldspray::case_file {

namespace {

constexpr int kKeyWidth = 26;

// Lists a material by its schema: one line per parameter, one block per group with the group's
// source at its foot.
class Printer {
 public:
  Printer(const materials::Material& m, std::ostream& out) : material_(m), out_(out) {}

  template <class T, class Codec>
  void scalar(std::string_view key, T& value, const Codec& codec, Presence) {
    line(key, codec.format(value));
    end_group(key);
  }

  void quantity(std::string_view key, double& value, units::Dimension dimension, Presence,
                const Range& = kAnyValue) {
    const std::string unit =
        dimension == units::kDimensionless ? "" : fmt::format(" {}", units::si_unit(dimension));
    line(key, shortest_text(value) + unit);
    end_group(key);
  }

  template <class T, class Alternative>
  void section_either(std::string_view key, T& value, Presence, std::type_identity<Alternative>) {
    line(key, "");
    nested(value);
    end_group(key);
  }

  template <class... Ts, std::size_t N>
  void variant(std::string_view key, std::variant<Ts...>& value, std::string_view tag,
               const std::array<std::string_view, N>& names, Presence) {
    line(key, fmt::format("{}: {}", tag, names[value.index()]));
    std::visit([&](auto& alternative) { nested(alternative); }, value);
    end_group(key);
  }

  // Sources are shown under each group.
  template <class... Args>
  void table(Args&&...) {}

  template <class... Args>
  void check(Args&&...) {}

 private:
  template <class T>
  void nested(T& value) {
    ++depth_;
    fields(*this, value);
    --depth_;
  }

  void line(std::string_view key, const std::string& value) {
    const std::string indented = std::string(2 * depth_, ' ') + std::string(key);
    if (value.empty()) {
      out_ << indented << '\n';
    } else {
      out_ << fmt::format("{:<{}} {}", indented, kKeyWidth, value) << '\n';
    }
  }

  void end_group(std::string_view key) {
    if (depth_ != 0) return;
    if (const auto it = material_.sources.find(std::string(key)); it != material_.sources.end()) {
      out_ << "  source: " << it->second << '\n';
    }
  }

  const materials::Material& material_;
  std::ostream& out_;
  int depth_ = 0;
};

}  // namespace

void print_material(const materials::Material& m, std::ostream& out) {
  out << "material " << m.name << " (values in SI units)\n";
  materials::Material copy = m;  // the schema functions take mutable references
  Printer printer(m, out);
  fields(printer, copy);
}

}  // namespace coldspray::case_file
