#include "core/softbody/simulation_series.h"

#include "core/base/math_constants.h"
#include "core/base/number_format.h"

#include <algorithm>
#include <cmath>

namespace granota {

SeriesRecorder::SeriesRecorder(std::size_t capacity, std::size_t bodyValues) : m_capacity(capacity), m_bodyValues(bodyValues) {}

namespace {

/// The values of a readout: total and the losses since the series began (first*).
SeriesValues valuesOf(const Readouts& r, double firstTotal, const std::optional<double>& firstDamping)
{
    SeriesValues v;
    v.kinetic = r.kineticEnergy;
    v.gravity = r.potentialEnergy;
    v.elastic = r.elasticEnergy;
    v.total = totalEnergy(r);
    v.areaErrorPercent = r.areaErrorPercent;
    v.maxStretch = r.maxStretch;
    v.contacts = r.contacts;
    if (r.dampingLoss && firstDamping) {
        v.dampingLoss = *r.dampingLoss - *firstDamping;
        v.otherLoss = firstTotal - v.total - *v.dampingLoss;
    }
    return v;
}

} // namespace

void SeriesRecorder::keepBodyValues(SeriesSample& s)
{
    if (m_bodyReadouts.size() != std::size_t(m_bodies))
        return; // not the bodies the series began with: none kept
    s.bodies.swap(m_spare);
    s.bodies.clear();
    s.bodies.reserve(m_bodyReadouts.size());
    for (std::size_t k = 0; k < m_bodyReadouts.size(); ++k)
        s.bodies.push_back(valuesOf(m_bodyReadouts[k], m_firstBodyTotal[k], m_firstBodyDamping[k]));
}

void SeriesRecorder::clear()
{
    m_samples.clear();
    m_started = false;
    m_lastAngles.clear();
    m_bodies = 0;
    m_bodySamples = 0;
    m_keepingBodies = false;
}

void SeriesRecorder::truncateAfter(long step)
{
    while (!m_samples.empty() && m_samples.back().step > step)
        m_samples.pop_back();
    if (m_samples.empty()) {
        clear();
        return;
    }
    m_lastStep = m_samples.back().step;
    m_lastAngles = m_samples.back().angles;
}

void SeriesRecorder::startKeepingBodies(long step)
{
    m_keepingBodies = true;
    m_bodiesFrom = step;
    m_firstBodyTotal.clear();
    m_firstBodyDamping.clear();
    for (const Readouts& b : m_bodyReadouts) {
        m_firstBodyTotal.push_back(totalEnergy(b));
        m_firstBodyDamping.push_back(b.dampingLoss);
    }
    m_bodySamples = std::max<std::size_t>(1, m_bodyValues / std::size_t(std::max(1, m_bodies)));
    if (m_capacity > 0)
        m_bodySamples = std::min(m_bodySamples, m_capacity);
}

void SeriesRecorder::setBodiesAsked(bool asked) { m_asked = asked && m_bodyValues > 0; }

const SeriesSample& SeriesRecorder::record(const Simulation& sim)
{
    if (m_started && sim.stepCount() <= m_lastStep)
        clear();
    const int bodies = m_started ? m_bodies : sim.bodyCount();
    // Each body's values from the series' start, or (many bodies) from when they are asked for.
    const bool start = !m_keepingBodies && m_bodyValues > 0 && bodies > 0 && (bodies <= kBodiesKeptUnasked || m_asked);
    const bool perBody = m_keepingBodies || start;
    const Readouts r = perBody ? sim.readoutsAndBodies(m_bodyReadouts) : sim.readouts();
    if (!m_started) {
        m_started = true;
        m_firstTotal = totalEnergy(r);
        m_firstDamping = r.dampingLoss;
        m_phaseLinks = 0;
        if (sim.scene().model == SceneModel::Pendulum && sim.chainCount() > 0) {
            std::vector<Point> joints;
            sim.chainJoints(0, joints);
            m_phaseLinks = joints.empty() ? 0 : static_cast<int>(joints.size()) - 1;
        }
        m_bodies = bodies;
    }
    if (start)
        startKeepingBodies(sim.stepCount());
    SeriesSample s;
    static_cast<SeriesValues&>(s) = valuesOf(r, m_firstTotal, m_firstDamping);
    s.step = sim.stepCount();
    if (m_keepingBodies)
        keepBodyValues(s);
    if (m_phaseLinks > 0) {
        std::vector<Point> joints;
        sim.chainJoints(0, joints);
        for (int k = 0; k < m_phaseLinks && k + 1 < static_cast<int>(joints.size()); ++k)
            s.angles.push_back(linkAngle(joints[std::size_t(k)], joints[std::size_t(k) + 1]));
        if (m_lastAngles.size() == s.angles.size() && !m_samples.empty()) {
            const double dt = static_cast<double>(s.step - m_lastStep);
            for (std::size_t k = 0; k < s.angles.size(); ++k)
                s.angularVelocities.push_back(wrapAngle(s.angles[k] - m_lastAngles[k]) / dt);
        }
        m_lastAngles = s.angles;
    }
    m_lastStep = s.step;
    m_samples.push_back(std::move(s));
    if (m_capacity > 0 && m_samples.size() > m_capacity)
        m_samples.pop_front();
    // Only the last m_bodySamples keep their bodies' values: let the one before them go.
    if (m_keepingBodies && m_samples.size() > m_bodySamples) {
        std::vector<SeriesValues>& old = m_samples[m_samples.size() - 1 - m_bodySamples].bodies;
        if (!old.empty())
            m_spare.swap(old);
        old.clear();
    }
    return m_samples.back();
}

std::string seriesCsvHeader(int phaseLinks)
{
    std::string h = "step,time_s,kinetic,gravity,elastic,total,damping_loss,other_loss,area_error_percent,max_stretch,"
                    "contacts";
    for (int k = 1; k <= phaseLinks; ++k)
        h += ",angle_" + std::to_string(k) + ",omega_" + std::to_string(k);
    return h;
}

std::string seriesCsvRow(const SeriesSample& s, int phaseLinks, int body)
{
    const auto opt = [](const std::optional<double>& v) { return v ? formatDouble(*v) : std::string(); };
    static const SeriesValues kNone;
    const SeriesValues* values = seriesValuesOf(s, body);
    const SeriesValues& v = values ? *values : kNone;
    std::string row = std::to_string(s.step) + "," + formatDouble(double(s.step) / kStepsPerSecond) + "," +
                      formatDouble(v.kinetic) + "," + formatDouble(v.gravity) + "," + opt(v.elastic) + "," +
                      formatDouble(v.total) + "," + opt(v.dampingLoss) + "," + opt(v.otherLoss) + "," +
                      formatDouble(v.areaErrorPercent) + "," + formatDouble(v.maxStretch) + "," + std::to_string(v.contacts);
    for (int k = 0; k < phaseLinks; ++k) {
        const std::size_t i = static_cast<std::size_t>(k);
        row += "," + (i < s.angles.size() ? formatDouble(s.angles[i]) : std::string()) + "," +
               (i < s.angularVelocities.size() ? formatDouble(s.angularVelocities[i]) : std::string());
    }
    return row;
}

} // namespace granota
