// Bond laws followed beside a run without acting on it. Runs that differ only in their bonding
// parameters move identically until one of them bonds a node, because D_bond acts on the
// mechanics only through bond_forms at the contact nodes (mpm/contact.hpp, thesis eq 4.7). A run
// carrying shadows keeps its own D_bond at zero, so it never bonds, and tracks for every shadow
// law the D_bond its surface points would have (eqs 4.5 / 4.16a) and that law's nodal sums of
// eq 4.6, accumulated in the order the run's own would be. The step at which a law's nodal D_bond
// first reaches 1 is where that law's run leaves the shared trajectory (run/bond_family.hpp).
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "bodies/bodies.hpp"
#include "bodies/points.hpp"
#include "bonding/bond_law.hpp"
#include "mpm/contact.hpp"

namespace coldspray::mpm {

class BondShadows {
 public:
  // Follows `laws` over the surface points of P; shadow k is laws[k] until one is dropped.
  void follow(const std::vector<bonding::BondLaw>& laws, const bodies::Points& P);
  bool active() const { return !laws_.empty(); }
  std::size_t size() const { return laws_.size(); }
  const bonding::BondLaw& law(std::size_t k) const { return laws_[k]; }
  // The index in follow()'s `laws` of shadow k.
  std::size_t id(std::size_t k) const { return ids_[k]; }

  // Eqs 4.5 / 4.16a for every shadow at surface point p in contact; threads may call it for
  // different points at once.
  void grow(std::size_t p, const Eigen::Matrix3d& stress, double d_eqps, const Eigen::Vector3d& n,
            double dt);
  // Eq 4.6's sums: zeroed for the step's contact slots, then point p's share at entry f (as
  // ContactNodes::bond_sum, called where that sum is).
  void clear_sums(const ContactNodes& c);
  void add_to_sums(std::size_t p, std::size_t f, double w) {
    const std::int32_t col = column_[p];
    for (std::size_t k = 0; k < laws_.size(); ++k)
      add_bond_share(bond_sum_[k][f], bond_[k][col], w);
  }
  // Whether shadow k's nodal D_bond (eq 4.7) holds at some pair of bodies at a contact node this
  // step: from then on its run differs from this one.
  // With activation (law k's critical penetration > 0), at the step its pair of bodies at a
  // contact node is activated (bodies::pair_activated): it bonds where it touches from then on.
  bool bonds_now(std::size_t k, const ContactNodes& c, case_file::NodalAverage average,
                 const std::vector<bodies::BodyRange>& bodies) const;

  // Shadow k's D_bond at P's surface points, and its sums into c.bond_sum: what the state would
  // hold, at this point of the step, had it run with law k.
  void impose(std::size_t k, bodies::Points& P, ContactNodes& c) const;
  // Shadow k's D_bond into P.bond for output; clear_bond() puts the zeros back.
  void write_bond(std::size_t k, bodies::Points& P) const;
  void clear_bond(bodies::Points& P) const;
  // Stops following shadow k (its run has left the trajectory); the last shadow takes its index.
  void drop(std::size_t k);
  // The points `gone` (ascending) have left the run (mpm/departures.hpp): their columns go, the
  // other columns keep their order.
  void remove_points(const std::vector<std::size_t>& gone);

 private:
  // Numbers the points with a column (column_ >= 0) in point order, and lists them in surface_.
  void number_columns();

  std::vector<bonding::BondLaw> laws_;
  std::vector<std::size_t> ids_;
  std::vector<std::int32_t> column_;       // per point: its column among the surface points, or -1
  std::vector<std::size_t> surface_;       // per column: the point
  std::vector<std::vector<double>> bond_;  // [shadow][column]: D_bond
  std::vector<std::vector<double>> bond_sum_;  // [shadow][contact entry]: sum D_bond N_I
};

}  // namespace coldspray::mpm
