// Multi-body grid contact (thesis §3.4 steps 4-6, §3.5.4). Body-wise nodal mass, momentum, force
// and mass gradient are kept only at nodes two or more bodies share (the multi-mesh at contact
// nodes of Ma et al.), so memory grows with the contact area, not with bodies x nodes.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "case/case.hpp"

namespace coldspray::mpm {

inline constexpr int kMaxBodiesPerNode = 4;

class ContactNodes {
 public:
  // Slots in use this step.
  std::size_t size() const { return count_; }
  // Forget all slots (keeps capacity).
  void clear() { count_ = 0; }
  // A new slot for grid node `node`; grows the storage only when its capacity is exceeded.
  std::int32_t add(std::size_t node);
  // The entry of body `b` at slot `s`, added if absent. Throws RunFault past kMaxBodiesPerNode.
  int entry(std::int32_t s, int b);
  // The entry of body `b` at slot `s`, or -1.
  int find(std::int32_t s, int b) const;

  std::size_t node(std::int32_t s) const { return node_[s]; }
  int body_count(std::int32_t s) const { return body_count_[s]; }
  int body(std::int32_t s, int e) const { return body_[flat(s, e)]; }
  static std::size_t flat(std::int32_t s, int e) {
    return static_cast<std::size_t>(s) * kMaxBodiesPerNode + e;
  }

  // Body-wise nodal quantities, indexed by flat(slot, entry).
  std::vector<double> mass;
  std::array<std::vector<double>, 3> momentum;
  std::array<std::vector<double>, 3> force;
  std::array<std::vector<double>, 3> mass_gradient;
  // The momentum the contact step added (eq 3.31 times dt), for the contact work on the points.
  std::array<std::vector<double>, 3> correction;
  // As GridFields::velocity and velocity_change, and the part of the latter contact made,
  // correction/m.
  std::array<std::vector<double>, 3> velocity;
  std::array<std::vector<double>, 3> velocity_change;
  std::array<std::vector<double>, 3> contact_velocity_change;

 private:
  void grow(std::size_t slots);
  std::size_t count_ = 0;
  std::vector<std::size_t> node_;
  std::vector<std::uint8_t> body_count_;
  std::vector<std::int16_t> body_;
};

// How the contact normal is chosen at a node, and friction.
struct ContactRule {
  case_file::ContactNormal normal = case_file::ContactNormal::MaxGradient;
  int normal_body = -1;                   // with ContactNormal::Body
  std::vector<double> reference_density;  // per body: MVG compares volume gradients
  double friction = 0.0;
};

// What the contact step did, for the history; and its per-step scratch.
struct ContactResult {
  // Per ordered body pair [a * bodies + b]: sum over the nodes they share of |grad m_a| / rho_a,
  // the weight that decides the pair's MVG master body.
  std::vector<double> gradient_weight;
  // Per ordered pair: 1 while a is the pair's MVG master, kept from step to step.
  std::vector<std::uint8_t> master;
  // Impulse received by body a from body b this step, flattened [a * bodies + b], N s.
  std::vector<std::array<double, 3>> impulse;
};

// For every pair of bodies at every contact node, in a fixed order: the approach test (eq 3.29)
// and, where they approach, the sticking correction (eq 3.31) reduced to its normal part, with
// a Coulomb-limited tangential part when friction > 0. Each correction changes the two bodies'
// momenta by equal and opposite amounts, and their forces by the same over dt.
// `held` is the grid's NodeConstraint bits: a held velocity component (a symmetry or roller
// plane through the node) is removed from the normal, which cannot point through that plane.
void resolve_contact(ContactNodes& contact, const ContactRule& rule,
                     const std::vector<std::uint8_t>& held, double dt, int bodies,
                     ContactResult& result);

}  // namespace coldspray::mpm
