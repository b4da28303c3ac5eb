#include "ui/frog/frog_tab.h"

#include "core/base/number_format.h"
#include "ui/common/error_text.h"
#include "ui/common/number_text.h"
#include "ui/common/value_command.h"
#include "ui/frog/frog_canvas.h"

#include <QDoubleSpinBox>
#include <QGroupBox>
#include <QLabel>
#include <QSpinBox>
#include <QUndoStack>

#include <algorithm>
#include <cmath>

/// \file frog_tab_knobs.cpp
/// FrogTab, part: the stable solver's knobs (docs/solvers.md#knobs), turned live as undo steps,
/// and their note: the period and frequency an edge of this scene rings at.

namespace granota::ui {

namespace {

constexpr int kStableMergeIdBase = 0x46530000; ///< "FS": a stable solver knob's edits merge (valueMergeId)

} // namespace

bool FrogTab::applyStableSettings(const StableSettings& settings, QString* error)
{
    // Live: the run goes on from where it is, and records the change at its step.
    if (!m_run->setStableSettings(settings)) {
        if (error)
            *error = tr("The stable solver's knobs were refused: substeps from %1 to %2, compliance from 0 to %3, "
                        "damping ratio from 0 to %4.")
                         .arg(StableSettings::kMinSubsteps)
                         .arg(StableSettings::kMaxSubsteps)
                         .arg(displayNumber(StableSettings::kMaxEdgeCompliance))
                         .arg(displayNumber(StableSettings::kMaxEdgeDampingRatio));
        return false;
    }
    showStableSettings();
    emit documentChanged();
    return true;
}

bool FrogTab::editStableSetting(const QString& key, double value, QString* error)
{
    SceneSpec changed = m_run->sceneInForce();
    const auto ok = applySetting(changed, key.toStdString() + "=" + formatDouble(value));
    if (!ok) {
        if (error)
            *error = tr("This value was refused: %1").arg(ErrorText::of(ok.error()));
        return false;
    }
    const StableSettings before = knobsInForce(), after = changed.stable;
    if (after == before)
        return true;
    if (!applyStableSettings(after, error))
        return false;
    // The undo entry names the knob by its label on screen, not its key in the file.
    const QLabel* label = key == QLatin1String("substeps")          ? m_substepsLabel
                          : key == QLatin1String("edge_compliance") ? m_complianceLabel
                                                                    : m_dampingLabel;
    m_undo->push(new ValueCommand<StableSettings>([this](const StableSettings& s) { applyStableSettings(s, nullptr); }, before,
                                                  after, tr("Change %1").arg(label->text().remove(QLatin1Char('&'))),
                                                  valueMergeId(kStableMergeIdBase, key),
                                                  {/*dropWhenUnchanged=*/false, /*appliedAlready=*/true}));
    return true;
}

std::optional<Simulation::EdgeSpring> FrogTab::edgeSpringShown() const
{
    const Simulation* sim = m_run->simulation();
    return sim && sim->bodyCount() > 0 ? sim->edgeSpring(0) : std::nullopt;
}

void FrogTab::showStableSettings()
{
    const QSignalBlocker b1(m_substeps), b2(m_compliance), b3(m_hertz), b4(m_damping);
    const StableSettings knobs = knobsInForce();
    m_knobsShown = knobs;
    m_substeps->setValue(knobs.substeps);
    m_compliance->setValue(knobs.edgeCompliance);
    m_damping->setValue(knobs.edgeDampingRatio);
    m_stableBox->setVisible(m_run->solver() == SolverKind::Stable);
    // What α means for this scene: the first edge of the first body, at rest, its vertex's mass.
    const auto spring = edgeSpringShown();
    // Rigid edges, or none: no frequency to state ("—").
    const double hertz = spring ? edgeRingHertz(knobs.edgeCompliance, spring->restLength, spring->vertexMass, kStepsPerSecond)
                                : 0.0;
    m_hertz->setEnabled(hertz > 0);
    m_hertz->setSpecialValueText(hertz > 0 ? QString() : QStringLiteral("—"));
    m_damping->setEnabled(spring.has_value());
    if (hertz > 0) {
        // The frequencies α from 0 to its largest gives, this edge's.
        const double softest = edgeRingHertz(StableSettings::kMaxEdgeCompliance, spring->restLength, spring->vertexMass,
                                             kStepsPerSecond);
        m_hertz->setRange(std::ceil(softest * 100) / 100, kMostEdgeHertz);
        m_hertz->setValue(hertz);
    } else {
        m_hertz->setRange(0, kMostEdgeHertz);
        m_hertz->setValue(0);
    }
    QString note;
    if (spring) {
        const double period = edgeRingPeriodSteps(knobs.edgeCompliance, spring->restLength, spring->vertexMass);
        if (std::isfinite(period))
            note = tr("An edge of %1 px rings with a period of %2 steps (%3 Hz at 60 steps a second); 0 makes the edges rigid.")
                       .arg(displayFixed(spring->restLength, 0), displayFixed(period, 1), displayFixed(hertz, 2));
        else
            note = tr("α = 0: the edges are rigid.");
    } else if (m_run->simulation()) {
        note = tr("This scene has no springs: the compliance and the damping ratio do nothing here.");
    }
    m_stableNote->setText(note);
}

} // namespace granota::ui
