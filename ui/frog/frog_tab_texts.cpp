#include "ui/frog/frog_tab.h"

#include "core/softbody/scenes/scene_texts.h"
#include "ui/common/number_text.h"
#include "ui/common/widest_text_width.h"
#include "ui/frog/frog_canvas.h"
#include "ui/frog/frog_parameters_panel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QGroupBox>
#include <QLabel>
#include <QPushButton>
#include <QRadioButton>
#include <QRegularExpression>
#include <QSlider>
#include <QSpinBox>

#include <algorithm>
#include <limits>

/// \file frog_tab_texts.cpp
/// FrogTab, part: its texts (every label and tooltip, retranslated on a change of language),
/// the scene's title, description and hint, and the timeline's step and stopwatch.

namespace granota::ui {

QString FrogTab::sceneTitle(const QString& name) const
{
    const SceneText* text = findSceneText(name.toStdString());
    return text ? QString::fromLatin1(text->section) + QLatin1Char(' ') +
                      QCoreApplication::translate(kSceneTextContext, text->title)
                : name;
}

QString FrogTab::sceneDescription(const QString& name) const
{
    const SceneText* text = findSceneText(name.toStdString());
    return text ? QCoreApplication::translate(kSceneTextContext, text->description) : QString();
}

QString FrogTab::sceneHint() const
{
    if (scene().model == SceneModel::Pendulum)
        return tr("The pendulum hangs from the mouse: move the mouse over the picture.");
    if (scene().model == SceneModel::Stage) {
        if (scene().components.empty())
            return tr("Move the mouse up and down: the radius is r = |mouseY − h/2| (§4.1).");
        if (scene().has(SceneComponent::Bounce))
            return tr("Click to start the polygon again at the mouse (§4.3).");
        return tr("Reset (R) drops the polygon again.");
    }
    return tr("Drag the body with the left button. Space drops a new one at the mouse and holds it until you let go "
              "(Annex II).");
}

QString FrogTab::hint() const
{
    return tr("Drag the body with the mouse; Space on the canvas spawns one at the mouse. P pauses, S steps, R resets.");
}

QString FrogTab::keyboardHint() const
{
    return tr("Keys: the arrows move the cursor, G grabs, L lays a ruler, Space spawns a body; P pauses, S steps, R "
              "resets.");
}

void FrogTab::retranslate()
{
    m_sceneBox->setTitle(tr("Scene"));
    m_sceneLabel->setText(tr("Stage"));
    for (int i = 0; i < m_sceneCombo->count(); ++i)
        m_sceneCombo->setItemText(i, sceneTitle(m_sceneCombo->itemData(i).toString()));
    m_sceneCombo->setToolTip(tr("The stages of chapter 4, in the thesis's order, and the future work of §5.2. "
                                "Each scene builds, draws and shows only its own components."));
    m_description->setText(sceneDescription(QString::fromStdString(scene().name)));
    m_solverLabel->setText(tr("Solver"));
    m_solverCombo->setItemText(0, tr("Seed (Annex II)"));
    m_solverCombo->setItemText(1, tr("Stable (XPBD)"));
    m_solverCombo->setToolTip(tr("Seed: the thesis's own schemes, reproduced faithfully (Annex II). Stable: beyond the "
                                 "thesis, position-based constraints with compliance (XPBD) that hold the target "
                                 "area and stay stable on stiff and extreme settings. Switching starts the scene again."));
    m_canvas->setAccessibleName(tr("Frog canvas"));
    m_canvas->setSceneSummary(tr("Scene %1, %2 solver")
                                  .arg(sceneTitle(QString::fromStdString(scene().name)),
                                       m_solverCombo->itemText(m_run->solver() == SolverKind::Stable ? 1 : 0)));
    m_pause->setText(m_pause->isChecked() ? tr("Run") : tr("Pause"));
    keepWidestTextWidth(m_pause, {tr("Run"), tr("Pause")}); // one width, running or not
    m_pause->setToolTip(tr("Pause or run the animation, one fixed step per frame at 60 frames per second (P)."));
    m_step->setText(tr("Step"));
    m_step->setToolTip(tr("One fixed step, as one call of actualitza() in Annex II; pauses first (S or .)."));
    m_speedLabel->setText(tr("Speed"));
    m_showPlots->setText(tr("Plots over time"));
    m_showPlots->setToolTip(tr("Under the canvas: the energies, what damping and the rest took, the area error, the "
                               "largest stretch and the contacts as the run goes on; the pendulums' phase plot. "
                               "Pause freezes them; they export as CSV."));
    m_speedCombo->setToolTip(tr("Slow motion steps once every few frames and fast runs several steps a frame: the "
                                "step itself never changes, so the seed goes through exactly the states of Annex II "
                                "([ slower, ] faster)."));
    m_timeline->setToolTip(tr("The run so far, step by step: drag to go back to any step (the run pauses there). "
                              "Running on replays what was recorded until a press on a body, a spawn or a change "
                              "takes over (, one step back, . one step on)."));
    m_timeline->setAccessibleName(tr("Timeline"));
    m_stableBox->setTitle(tr("Stable solver"));
    m_substepsLabel->setText(tr("Substeps n"));
    m_substeps->setToolTip(tr("Substeps per step, 1 to 32: each step is cut into n substeps, and the constraints' error "
                              "falls like 1/n² at a cost proportional to n. The run goes on with it from the next step, and the "
                              "recording keeps the change."));
    m_complianceLabel->setText(tr("Edge compliance α"));
    m_compliance->setToolTip(tr("How soft the body's edges are, in step² per unit of mass and per px of rest length: "
                                "0 is rigid, larger is softer. Unlike the seed's factors it does not depend on the "
                                "substeps or the number of vertices. The run goes on with it from the next step, and the "
                                "recording keeps the change."));
    m_hertzLabel->setText(tr("Edge frequency f"));
    m_hertz->setSuffix(tr(" Hz"));
    m_hertz->setToolTip(tr("The same stiffness as a frequency, as Box2D states its soft constraints: how many times a "
                           "second an edge of this body rings on its own (α = 0, rigid, rings at none). Setting it sets "
                           "the compliance."));
    m_dampingLabel->setText(tr("Edge damping ratio ζ"));
    m_damping->setToolTip(tr("A dashpot along each edge, as a damping ratio: 0 none, 1 critical (an edge stretched and "
                             "let go comes back without ringing), above 1 slower still. What it takes shows in the "
                             "plots as damping. The run goes on with it from the next step, and the recording keeps "
                             "the change."));
    m_softBodyReport->setText(tr("Error against substeps…"));
    m_softBodyReport->setToolTip(tr("The soft-body report below the tab: XPBD's constraint error against the substeps "
                                    "and their cost (View ▸ Error against run time)."));
    showStableSettings();
    m_explosionText->setText(tr("The body has blown up."));
    m_explosionStable->setText(tr("Use the Stable solver"));
    m_explosionStable->setToolTip(tr("The same scene and values on the stable solver (XPBD), which holds them."));
    m_timelineDigits = -1; // the label's width, for this language's text
    m_markButton->setText(tr("Stopwatch"));
    m_markButton->setToolTip(tr("Marks the step shown; the label then counts the steps and seconds since it, as the "
                                "run goes on or the timeline moves (M). Again: clears the mark."));
    updateTimeline();
    m_reset->setText(tr("Reset"));
    m_reset->setToolTip(tr("Start the scene again with the current parameters (R)."));
    m_explosionReset->setText(m_reset->text()); // the same Reset, where the warning is
    m_explosionReset->setToolTip(m_reset->toolTip());
    m_solverNote->setText(tr("The seed solver has no angle constraints: these shapes round into blobs. The Stable "
                             "solver keeps their form."));
    m_solverNote->setVisible(m_run->solver() == SolverKind::Seed && seedRoundsShapes(scene()));

    m_bezierBox->setTitle(tr("Bézier outline (§4.9)"));
    m_precomputed->setText(tr("Precomputed points"));
    m_precomputed->setToolTip(tr("The thesis's choice (§4.9, §4.10): the polygon is the control polygon of a Bézier "
                                 "curve sampled once by De Casteljau (Def 2.4); the samples are the body's vertices."));
    m_fit->setText(tr("Least-squares fit every frame"));
    m_fit->setToolTip(tr("The option §4.9 abandoned as too costly for Processing: every frame, the least-squares "
                         "Bézier curve through the outline (Lemma 2.2, Prop 2.2). With M⁺ computed once, a frame "
                         "costs one small matrix product; the curve need not pass through the vertices (Note 2.3)."));
    if (!m_fit->isChecked())
        m_fitCost->setText(tr("Precomputed points: nothing to compute per frame."));
    else
        m_fitCost->setText(tr("Cost of the fit: %1 µs per frame.").arg(displayFixed(m_canvas->fitMicroseconds(), 1)));

    m_paramBox->setTitle(tr("Parameters"));
    m_paramBox->setToolTip(tr("Only this scene's parameters, with the names of Annex II. Changes apply at once: the "
                              "scene starts again with them."));
    m_params->retranslate();

    m_overlayBox->setTitle(tr("Overlays"));
    for (std::size_t i = 0; i < m_overlayBoxes.size(); ++i) {
        const FrogOverlay& overlay = frogOverlays()[i];
        m_overlayBoxes[i]->setText(QCoreApplication::translate(kFrogOverlayContext, overlay.label));
        m_overlayBoxes[i]->setToolTip(QCoreApplication::translate(kFrogOverlayContext, overlay.tip));
    }
    m_hint->setText(sceneHint());
}

void FrogTab::updateTimeline()
{
    const long end = m_run->recordedSteps();
    const long now = m_run->simulation() ? m_run->simulation()->stepCount() : 0;
    const int top = int(std::min<long>(end, std::numeric_limits<int>::max()));
    if (m_timeline->maximum() != top || (!m_timeline->isSliderDown() && m_timeline->value() != now)) {
        const QSignalBlocker block(m_timeline);
        m_timeline->setMaximum(top);
        if (!m_timeline->isSliderDown())
            m_timeline->setValue(int(std::min<long>(now, top)));
    }
    // A knob turned at a step the run replays or goes back past: the boxes show it.
    if (m_stableBox && knobsInForce() != m_knobsShown)
        showStableSettings();
    if (m_mark > end) // the run was cut off before the mark
        m_mark = -1;
    if (m_markButton->isChecked() != (m_mark >= 0)) {
        const QSignalBlocker block(m_markButton);
        m_markButton->setChecked(m_mark >= 0);
    }
    const QString text = tr("Step %1 of %2 · %3 s");
    QString shown = text.arg(now).arg(end).arg(displayFixed(double(now) / kStepsPerSecond, 2));
    if (m_mark >= 0) {
        const long since = now - m_mark, steps = std::labs(since);
        const QString seconds = displayFixed(double(steps) / kStepsPerSecond, 2);
        shown += QLatin1Char('\n') + (since >= 0 ? tr("%1 s (%n steps) since step %2", "", int(steps))
                                                 : tr("%1 s (%n steps) before step %2", "", int(steps)))
                                         .arg(seconds)
                                         .arg(m_mark);
    }
    m_timelineLabel->setText(shown);
    // Room for the stopwatch's second line, marked or not: the canvas keeps its size when it appears.
    m_timelineLabel->setMinimumHeight(2 * m_timelineLabel->fontMetrics().lineSpacing());
    // As wide as the widest text with this many digits, so that the slider does not jitter.
    const int digits = int(QString::number(end).size());
    if (digits == m_timelineDigits)
        return;
    m_timelineDigits = digits;
    const QString eights = QString(digits, QLatin1Char('8'));
    const int wide = m_timelineLabel->fontMetrics().horizontalAdvance(
        text.arg(eights, eights)
            .arg(displayFixed(double(end) / kStepsPerSecond, 2)
                     .replace(QRegularExpression(QStringLiteral("\\d")), QStringLiteral("8"))));
    m_timelineLabel->setMinimumWidth(wide);
}

} // namespace granota::ui
