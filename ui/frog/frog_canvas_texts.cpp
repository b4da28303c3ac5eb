#include "ui/frog/frog_canvas.h"
#include "ui/common/number_text.h"

#include "core/softbody/outline.h"

#include <cmath>

// The Frog canvas's text panel: what it says over the scene, line by line (frog_canvas.h,
// textLines), from the run, the overlays chosen and the timings.

namespace granota::ui {

QStringList FrogCanvas::composeTexts(bool blownUpLine)
{
    QStringList lines;
    const auto num = [](double v, int decimals) { return displayFixed(v, decimals); };
    if (sim()) {
        const SceneSpec& scene = sim()->scene();
        if (blownUpLine) {
            const double error = sim()->readouts().areaErrorPercent;
            lines << tr("The body has blown up (area error %1 %): press Reset (R), or switch to the Stable solver")
                         .arg(!std::isfinite(error) ? QStringLiteral("∞")
                                                    : (error > 0 ? QStringLiteral("+") : QString()) + displayFixed(error, 0));
        }
        if (const Simulation* ghost = m_run->ghost()) {
            const Simulation& g = *ghost;
            const bool seed = g.solver() == SolverKind::Seed;
            if (g.bodyCount() > 0)
                lines << (seed ? tr("Dashed ghost: the seed solver fed the same mouse, area error %1 %")
                               : tr("Dashed ghost: the stable solver fed the same mouse, area error %1 %"))
                             .arg(num(g.readouts().areaErrorPercent, 1));
            else
                lines << (seed ? tr("Dashed ghost: the seed solver fed the same mouse")
                               : tr("Dashed ghost: the stable solver fed the same mouse"));
        }
        if (m_overlays.pairs) {
            sim()->broadPhasePairs(m_pairs);
            lines << (sim()->solver() == SolverKind::Seed
                          ? tr("Broad phase: none, the seed has no collisions (§5.2 is future work)")
                          : tr("Broad phase: %n candidate pairs, %1 contacts", "", int(m_pairs.size()))
                                .arg(sim()->readouts().contacts));
        }
        if (m_overlays.protractor) {
            int limited = 0, held = 0;
            for (int c = 0; c < sim()->chainCount(); ++c) {
                readLinkAngles(*sim(), c, m_joints, m_angles);
                for (const LinkAngleReading& a : m_angles) {
                    limited += a.limit ? 1 : 0;
                    held += a.atLimit ? 1 : 0;
                }
            }
            lines << (limited == 0 ? tr("Protractor: no joint of this scene has angle limits")
                                   : tr("Protractor: %n of %1 joints held at a limit (red)", "", held).arg(limited));
        }
        if (m_overlays.trail)
            lines << (m_run->trailPoint().joint ? tr("Trail of joint %1 of chain %2 (Shift+click a point to follow another)")
                                                : tr("Trail of vertex %1 of body %2 (Shift+click a point to follow another)"))
                         .arg(m_run->trailPoint().index)
                         .arg(m_run->trailPoint().owner + 1);
        if (m_run->playingBack())
            lines << tr("Replaying the recorded run, step %1 of %2: a press on a body takes over from there")
                         .arg(sim()->stepCount())
                         .arg(m_run->recordedSteps());
        if (const int slower = m_run->workFramesPerStep(); slower > 1)
            lines << tr("Running %n× slower than real time: a step of this scene is more work than a frame holds", "", slower);
        if (m_run->speed() < 1)
            lines << tr("Slow motion, %1× real time: one step every %n frames, the step itself unchanged", "",
                        m_run->framesPerStep())
                         .arg(FrogRun::speedLabel(m_run->speed()));
        else if (m_run->speed() > 1)
            lines << tr("Fast, %1× real time: %n steps a frame", "", m_run->stepsPerFrame())
                         .arg(FrogRun::speedLabel(m_run->effectiveSpeed()));
        if (scene.has(SceneComponent::OutlineBezier)) {
            if (const OutlineFitter* fitter = m_scenePainter.fitter(); bezierOutline() == BezierOutline::Fit)
                lines << tr("Least-squares Bézier fit, degree %1 through %2 points: %3 µs per frame")
                             .arg(fitter ? fitter->degree() : scene.bezierFitDegree)
                             .arg(fitter ? fitter->vertexCount() + 1 : scene.bezierSamples + 1)
                             .arg(num(fitMicroseconds(), 1));
            else
                lines << tr("Precomputed Bézier points (§4.9): computed once, nothing per frame");
        }
        // With several bodies each figure says whose it is: the area line is the first body's,
        // the solver's area error the mean over all of them.
        const int bodies = sim()->bodyCount();
        if (m_overlays.area && bodies > 0) {
            const double area = sim()->bodyArea(0), target = sim()->bodyTargetArea(0);
            if (bodies > 1 && target > 0)
                lines << tr("Body 1 of %1: area %2 px² · target %3 px² (%4 %)")
                             .arg(bodies)
                             .arg(num(area, 0), num(target, 0), num(100 * (area - target) / target, 1));
            else if (bodies > 1)
                lines << tr("Body 1 of %1: area %2 px² · target %3 px²").arg(bodies).arg(num(area, 0), num(target, 0));
            else if (target > 0)
                lines << tr("Area %1 px² · target %2 px² (%3 %)")
                             .arg(num(area, 0), num(target, 0), num(100 * (area - target) / target, 1));
            else
                lines << tr("Area %1 px² · target %2 px²").arg(num(area, 0), num(target, 0));
        }
        if (m_overlays.readouts) {
            const Readouts r = sim()->readouts();
            if (bodies > 1)
                lines << tr("Area error, mean of the %1 bodies, %2 % · largest stretch %3 %")
                             .arg(bodies)
                             .arg(num(r.areaErrorPercent, 2), num(100 * r.maxStretch, 1));
            else
                lines << tr("Area error %1 % · largest stretch %2 %").arg(num(r.areaErrorPercent, 2), num(100 * r.maxStretch, 1));
            lines << tr("Largest correction %1 · kinetic energy %2 · potential energy %3")
                         .arg(num(r.constraintForce, 3), num(r.kineticEnergy, 1), num(r.potentialEnergy, 0));
        }
        if (m_overlays.velocities && sim()->bodyCount() == 0)
            lines << tr("Velocities: this scene has no soft body");
        if (m_overlays.frameTime) {
            const double frameMs = m_run->frameMs(), stepMs = m_run->stepMs();
            if (m_run->running())
                lines << tr("Frame %1 ms (%2 frames per second) · step %3 ms · drawing %4 ms")
                             .arg(num(frameMs, 1), num(frameMs > 0 ? 1000 / frameMs : 0.0, 0), num(stepMs, 3),
                                  num(m_drawShownMs, 2));
            else
                lines << tr("Paused · step %1 ms · drawing %2 ms").arg(num(stepMs, 3), num(m_drawShownMs, 2));
            lines << tr("Step %1").arg(sim()->stepCount());
        }
    }
    return lines;
}

} // namespace granota::ui
