#pragma once
/// \file simulation_series.h
/// The plots over time of a running scene: one sample per step of its energies, what
/// damping and the rest took, its area error, largest stretch and contacts, and for the
/// pendulums each link's angle and angular velocity (the phase plot). The Frog tab's plot
/// panel draws these samples and exports them; `granota-cli simulate --series F.csv`
/// writes the same columns (docs/plots-over-time.md).

#include "core/softbody/seed_angle.h" // linkAngle
#include "core/softbody/simulation.h"

#include <cstddef>
#include <deque>
#include <optional>
#include <string>
#include <vector>

namespace granota {

/// The values of one row of the series, summed over the scene or of one body.
/// Energies in mass·px²/step² (the seed: unit masses).
struct SeriesValues {
    double kinetic = 0;
    double gravity = 0;            ///< Readouts::potentialEnergy
    std::optional<double> elastic; ///< stable solver only (Readouts::elasticEnergy)
    double total = 0;              ///< kinetic + gravity + elastic (where known)
    /// What damping took since the series began (stable solver only).
    std::optional<double> dampingLoss;
    /// The rest of the drop since the series began, total₀ − total − dampingLoss: what the
    /// contacts (inelastic hits, wall and body friction), the velocity cap and the solver's
    /// own dissipation took, less what the mouse put in (negative when it put in more). Of
    /// one body, also what it gave to the others it hit, less what they gave it.
    std::optional<double> otherLoss;
    double areaErrorPercent = 0;
    double maxStretch = 0;
    int contacts = 0;
};

/// One row of the series: the scene's values and, while they are kept, each body's.
struct SeriesSample : SeriesValues {
    long step = 0;
    /// Each body's values (Simulation::bodyReadouts), body 0 first; empty in a sample older
    /// than the recorder keeps them (SeriesRecorder::bodySamplesKept), and with no bodies.
    std::vector<SeriesValues> bodies;
    /// Pendulum scenes: each link's angle from the downward vertical, growing towards −x
    /// (as the seed's limits of §4.15 measure it), rad, in (−π, π].
    std::vector<double> angles;
    /// dθ/dt of each link, rad/step, from the sample before (empty in the first sample).
    std::vector<double> angularVelocities;
};

/// The values of sample s the plots and the CSV show: the scene's (body −1) or body k's;
/// nullptr where that body's values are not kept.
inline const SeriesValues* seriesValuesOf(const SeriesSample& s, int body)
{
    if (body < 0)
        return &s;
    return std::size_t(body) < s.bodies.size() ? &s.bodies[std::size_t(body)] : nullptr;
}

/// Records the samples of one run, from the state it is first given.
class SeriesRecorder {
public:
    /// Every body's values in a sample count against this many, all samples together: a
    /// frog's are kept as long as the samples (36 000), 200 frogs' for 1000 samples (16 s).
    static constexpr std::size_t kBodyValuesKept = 200000;
    /// Each body's values are kept from the series' start in a scene of at most this many
    /// bodies; with more (they cost a step of 1000 bodies some 10 %), from when setBodiesAsked()
    /// asks for them.
    static constexpr int kBodiesKeptUnasked = 64;

    /// Keeps the last `capacity` samples (0: all of them), and each body's values in as
    /// many of the last as `bodyValues` allows (0: none).
    explicit SeriesRecorder(std::size_t capacity = 0, std::size_t bodyValues = kBodyValuesKept);

    /// Samples the simulation's present state and appends it; a simulation at a step not
    /// after the last sample's (a new run, a reset) starts the series again.
    const SeriesSample& record(const Simulation& sim);
    void clear();
    /// Drops the samples after `step` (a run gone back to it: docs/rewind.md); the next
    /// record() goes on from the last one kept. None kept: the series starts again.
    void truncateAfter(long step);

    const std::deque<SeriesSample>& samples() const { return m_samples; }
    /// Links in the phase columns (0 outside the pendulum scenes).
    int phaseLinks() const { return m_phaseLinks; }
    std::size_t capacity() const { return m_capacity; }
    /// Bodies in the scene of the series.
    int bodies() const { return m_bodies; }
    /// Whether the samples keep each body's values (SeriesSample::bodies), and from which step.
    bool keepsBodies() const { return m_keepingBodies; }
    long bodiesKeptFrom() const { return m_bodiesFrom; }
    /// How many of the last samples keep each body's values.
    std::size_t bodySamplesKept() const { return m_bodySamples; }
    /// Asked, each body's values are kept from the next sample on in any scene, in this
    /// series and the next ones (none when constructed with no room for them); no longer
    /// asked, a series that keeps them goes on, and the next one of many bodies does not.
    void setBodiesAsked(bool asked);
    bool bodiesAsked() const { return m_asked; }

private:
    void keepBodyValues(SeriesSample& s);
    void startKeepingBodies(long step);

    std::size_t m_capacity;
    std::size_t m_bodyValues;
    std::size_t m_bodySamples = 0;
    int m_bodies = 0;
    bool m_keepingBodies = false;
    bool m_asked = false;
    long m_bodiesFrom = 0;
    std::vector<double> m_firstBodyTotal;
    std::vector<std::optional<double>> m_firstBodyDamping;
    std::vector<Readouts> m_bodyReadouts; // scratch
    std::vector<SeriesValues> m_spare;    // the buffer of the sample whose bodies were let go
    std::deque<SeriesSample> m_samples;
    int m_phaseLinks = 0;
    bool m_started = false;
    double m_firstTotal = 0;
    std::optional<double> m_firstDamping;
    long m_lastStep = 0;
    std::vector<double> m_lastAngles;
};

/// The CSV header: step,time_s,kinetic,gravity,elastic,total,damping_loss,other_loss,
/// area_error_percent,max_stretch,contacts, then angle_k,omega_k for each phase link.
std::string seriesCsvHeader(int phaseLinks);
/// One CSV row of the scene's values or (body ≥ 0) of one body's, which must be kept in
/// the sample; an unknown value (the seed's elastic energy) is an empty field.
std::string seriesCsvRow(const SeriesSample& sample, int phaseLinks, int body = -1);

} // namespace granota
