#pragma once
/// \file follow_chain.h
/// The revised pendulum of §4.14: a chain of joints whose first joint (the "clau") is put
/// where it is wanted each step; then, one by one from the clau outwards, each joint is
/// put back at its distance from the previous (already corrected) joint, along the line
/// that joins them. Purely kinematic: no gravity, no velocity (those come in §4.15).

#include "core/base/vec2.h"

#include <vector>

namespace granota {

class FollowChain {
public:
    /// Joints start in a horizontal line to the right of `clau`; lengths ≥ 0.
    FollowChain(Point clau, std::vector<double> lengths);
    /// §4.14: move the clau, then correct every following joint in order.
    void follow(Point clau);
    const std::vector<Point>& joints() const { return m_joints; }
    const std::vector<double>& lengths() const { return m_lengths; }

private:
    std::vector<Point> m_joints;
    std::vector<double> m_lengths;
};

} // namespace granota
