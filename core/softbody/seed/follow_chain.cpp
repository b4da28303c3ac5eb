#include "core/softbody/seed/follow_chain.h"

#include <cmath>

namespace granota {

FollowChain::FollowChain(Point clau, std::vector<double> lengths) : m_lengths(std::move(lengths))
{
    m_joints.push_back(clau);
    for (double l : m_lengths)
        m_joints.emplace_back(m_joints.back().x + l, m_joints.back().y);
}

void FollowChain::follow(Point clau)
{
    if (!std::isfinite(clau.x) || !std::isfinite(clau.y))
        return;
    m_joints[0] = clau;
    for (std::size_t i = 1; i < m_joints.size(); ++i) {
        const Point d = m_joints[i] - m_joints[i - 1];
        const double len = norm(d);
        const double want = m_lengths[i - 1];
        if (len == want)
            continue; // §4.14: already at its distance
        // Along the line from the previous joint; a joint sitting exactly on the previous
        // one has no direction and hangs straight down.
        const Point u = len > 0 ? Point(d.x / len, d.y / len) : Point(0, 1);
        m_joints[i] = Point(m_joints[i - 1].x + want * u.x, m_joints[i - 1].y + want * u.y);
    }
}

} // namespace granota
