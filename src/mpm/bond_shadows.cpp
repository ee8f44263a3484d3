#include "mpm/bond_shadows.hpp"

#include <algorithm>
#include <cassert>
#include <utility>

#include "mpm/erase_indices.hpp"

namespace coldspray::mpm {

void BondShadows::follow(const std::vector<bonding::BondLaw>& laws, const bodies::Points& P) {
  laws_ = laws;
  ids_.resize(laws.size());
  for (std::size_t k = 0; k < laws.size(); ++k) ids_[k] = k;
  column_.resize(P.size());
  for (std::size_t p = 0; p < P.size(); ++p) column_[p] = P.surface[p] ? 0 : -1;
  number_columns();
  bond_.assign(laws.size(), std::vector<double>(surface_.size(), 0.0));
  bond_sum_.assign(laws.size(), {});
}

void BondShadows::number_columns() {
  surface_.clear();
  for (std::size_t p = 0; p < column_.size(); ++p)
    if (column_[p] >= 0) {
      column_[p] = static_cast<std::int32_t>(surface_.size());
      surface_.push_back(p);
    }
}

void BondShadows::grow(std::size_t p, const Eigen::Matrix3d& stress, double d_eqps,
                       const Eigen::Vector3d& n, double dt) {
  const std::int32_t col = column_[p];
  assert(col >= 0);  // only surface points touch (mark_touching_points)
  if (d_eqps <= 0.0 || laws_.empty()) return;
  // The laws share their model (run_bond_family checks), so the drive is computed once.
  const double drive = bonding::bond_drive(laws_[0].model, stress, d_eqps, n);
  for (std::size_t k = 0; k < laws_.size(); ++k)
    bond_[k][col] += bonding::bond_increment_from_drive(laws_[k], drive, d_eqps, dt);
}

// Grows only when the contact storage has (ContactNodes::add), not step by step.
void BondShadows::clear_sums(const ContactNodes& c) {
  const std::size_t entries = c.size() * kMaxBodiesPerNode;
  for (auto& sums : bond_sum_) {
    if (sums.size() < c.bond_sum.size()) sums.resize(c.bond_sum.size());
    std::fill(sums.begin(), sums.begin() + static_cast<std::ptrdiff_t>(entries), 0.0);
  }
}

// Every pair at every slot, also those the contact step skips for want of a normal: a shadow
// that leaves a step early only costs its run that step alone, one that left late would be wrong.
bool BondShadows::bonds_now(std::size_t k, const ContactNodes& c, case_file::NodalAverage average,
                            const std::vector<bodies::BodyRange>& bodies) const {
  const double critical = laws_[k].critical_penetration;
  for (std::size_t s = 0; s < c.size(); ++s) {
    const auto slot = static_cast<std::int32_t>(s);
    for (int e1 = 0; e1 < c.body_count(slot); ++e1)
      for (int e2 = e1 + 1; e2 < c.body_count(slot); ++e2) {
        const bool bonds =
            critical > 0.0 ? bodies::pair_activated(bodies[c.body(slot, e1)].penetration,
                                                    bodies[c.body(slot, e2)].penetration, critical)
                           : bond_forms(nodal_bond(c, bond_sum_[k], slot, e1, e2, average));
        if (bonds) return true;
      }
  }
  return false;
}

void BondShadows::impose(std::size_t k, bodies::Points& P, ContactNodes& c) const {
  write_bond(k, P);
  const std::size_t entries = c.size() * kMaxBodiesPerNode;
  std::copy(bond_sum_[k].begin(), bond_sum_[k].begin() + static_cast<std::ptrdiff_t>(entries),
            c.bond_sum.begin());
}

void BondShadows::write_bond(std::size_t k, bodies::Points& P) const {
  for (std::size_t col = 0; col < surface_.size(); ++col) P.bond[surface_[col]] = bond_[k][col];
}

void BondShadows::clear_bond(bodies::Points& P) const {
  for (const std::size_t p : surface_) P.bond[p] = 0.0;
}

void BondShadows::drop(std::size_t k) {
  const std::size_t last = laws_.size() - 1;
  if (k != last) {
    laws_[k] = laws_[last];
    ids_[k] = ids_[last];
    std::swap(bond_[k], bond_[last]);
    std::swap(bond_sum_[k], bond_sum_[last]);
  }
  laws_.pop_back();
  ids_.pop_back();
  bond_.pop_back();
  bond_sum_.pop_back();
}

// In the rare step where points leave: the list of their columns is allocated.
void BondShadows::remove_points(const std::vector<std::size_t>& gone) {
  if (column_.empty()) return;  // never followed any law
  std::vector<std::size_t> gone_columns;
  for (const std::size_t p : gone)
    if (column_[p] >= 0) gone_columns.push_back(static_cast<std::size_t>(column_[p]));
  erase_indices(column_, gone);
  for (auto& bond : bond_) erase_indices(bond, gone_columns);
  number_columns();
}

}  // namespace coldspray::mpm
