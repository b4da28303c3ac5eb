#include "core/softbody/simulation_series.h"

#include "core/base/math_constants.h"
#include "core/base/number_format.h"

#include <cmath>

namespace granota {

SeriesRecorder::SeriesRecorder(std::size_t capacity) : m_capacity(capacity) {}

void SeriesRecorder::clear()
{
    m_samples.clear();
    m_started = false;
    m_lastAngles.clear();
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

const SeriesSample& SeriesRecorder::record(const Simulation& sim)
{
    if (m_started && sim.stepCount() <= m_lastStep)
        clear();
    const Readouts r = sim.readouts();
    SeriesSample s;
    s.step = sim.stepCount();
    s.kinetic = r.kineticEnergy;
    s.gravity = r.potentialEnergy;
    s.elastic = r.elasticEnergy;
    s.total = s.kinetic + s.gravity + r.elasticEnergy.value_or(0);
    s.areaErrorPercent = r.areaErrorPercent;
    s.maxStretch = r.maxStretch;
    s.contacts = r.contacts;
    if (!m_started) {
        m_started = true;
        m_firstTotal = s.total;
        m_firstDamping = r.dampingLoss;
        m_phaseLinks = 0;
        if (sim.scene().model == SceneModel::Pendulum && sim.chainCount() > 0) {
            std::vector<Point> joints;
            sim.chainJoints(0, joints);
            m_phaseLinks = joints.empty() ? 0 : static_cast<int>(joints.size()) - 1;
        }
    }
    if (r.dampingLoss && m_firstDamping) {
        s.dampingLoss = *r.dampingLoss - *m_firstDamping;
        s.otherLoss = m_firstTotal - s.total - *s.dampingLoss;
    }
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

std::string seriesCsvRow(const SeriesSample& s, int phaseLinks)
{
    const auto opt = [](const std::optional<double>& v) { return v ? formatDouble(*v) : std::string(); };
    std::string row = std::to_string(s.step) + "," + formatDouble(double(s.step) / kStepsPerSecond) + "," +
                      formatDouble(s.kinetic) + "," + formatDouble(s.gravity) + "," + opt(s.elastic) + "," +
                      formatDouble(s.total) + "," + opt(s.dampingLoss) + "," + opt(s.otherLoss) + "," +
                      formatDouble(s.areaErrorPercent) + "," + formatDouble(s.maxStretch) + "," +
                      std::to_string(s.contacts);
    for (int k = 0; k < phaseLinks; ++k) {
        const std::size_t i = static_cast<std::size_t>(k);
        row += "," + (i < s.angles.size() ? formatDouble(s.angles[i]) : std::string()) + "," +
               (i < s.angularVelocities.size() ? formatDouble(s.angularVelocities[i]) : std::string());
    }
    return row;
}

} // namespace granota
