#include "ui/frog/frog_overlays.h"

#include "core/softbody/scenes/translatable_text.h"

namespace granota::ui {

bool FrogOverlays::operator==(const FrogOverlays& o) const
{
    for (const FrogOverlay& overlay : frogOverlays())
        if (this->*overlay.flag != o.*overlay.flag)
            return false;
    return true;
}

const std::array<FrogOverlay, kFrogOverlayCount>& frogOverlays()
{
    // key, flag, label, tooltip
    static const std::array<FrogOverlay, kFrogOverlayCount> table = {{
        {"vertices", &FrogOverlays::vertices, QT_TRANSLATE_NOOP("granota::ui::FrogTab", "Vertices"),
         QT_TRANSLATE_NOOP("granota::ui::FrogTab",
                           "The body's vertices, numbered as in Annex II's arrays (v₀ under the head), and the "
                           "joints of the legs.")},
        {"springs", &FrogOverlays::springs, QT_TRANSLATE_NOOP("granota::ui::FrogTab", "Springs"),
         QT_TRANSLATE_NOOP("granota::ui::FrogTab",
                           "The polygon's edges: the springs of §4.4 that keep neighbours at their length.")},
        {"area", &FrogOverlays::area, QT_TRANSLATE_NOOP("granota::ui::FrogTab", "Area vs target"),
         QT_TRANSLATE_NOOP("granota::ui::FrogTab",
                           "The body's area by the trapezoid rule against the target area (§4.5); the bar's "
                           "mark is the target.")},
        {"velocities", &FrogOverlays::velocities, QT_TRANSLATE_NOOP("granota::ui::FrogTab", "Velocities"),
         QT_TRANSLATE_NOOP("granota::ui::FrogTab",
                           "Each vertex's move in the last step, x − x_prev (Verlet, Def 3.1), drawn four "
                           "times longer.")},
        {"readouts", &FrogOverlays::readouts, QT_TRANSLATE_NOOP("granota::ui::FrogTab", "Readouts"),
         QT_TRANSLATE_NOOP("granota::ui::FrogTab", "What the solver measures: area error, largest stretch of an edge, largest "
                                                   "correction or constraint force, kinetic and potential energy.")},
        {"frame_time", &FrogOverlays::frameTime, QT_TRANSLATE_NOOP("granota::ui::FrogTab", "Frame time"),
         QT_TRANSLATE_NOOP("granota::ui::FrogTab",
                           "Time per frame and per simulation step, in milliseconds, averaged a few times a "
                           "second.")},
        {"ghost", &FrogOverlays::ghost, QT_TRANSLATE_NOOP("granota::ui::FrogTab", "Ghost of the other solver"),
         QT_TRANSLATE_NOOP("granota::ui::FrogTab",
                           "Both solvers at once: the other solver runs the same scene, fed the same mouse, and "
                           "is drawn dashed over this one (the seed's frog sits about 17 % short of its area, "
                           "the stable one holds it).")},
        {"trail", &FrogOverlays::trail, QT_TRANSLATE_NOOP("granota::ui::FrogTab", "Trail"),
         QT_TRANSLATE_NOOP("granota::ui::FrogTab",
                           "The path of one point over the last 10 s: the pendulum's tip or the first body's vertex 0; "
                           "Shift+click on a vertex or a joint to follow it.")},
        {"pairs", &FrogOverlays::pairs, QT_TRANSLATE_NOOP("granota::ui::FrogTab", "Broad phase"),
         QT_TRANSLATE_NOOP("granota::ui::FrogTab",
                           "§5.2.2: the pairs of bodies whose boxes overlap, the only ones tested for contact "
                           "(a uniform grid finds them), and how many contacts there are (stable solver).")},
        {"protractor", &FrogOverlays::protractor, QT_TRANSLATE_NOOP("granota::ui::FrogTab", "Protractor"),
         QT_TRANSLATE_NOOP("granota::ui::FrogTab",
                           "§4.15: each joint's angle, in degrees, over the range its limits allow (shaded); red "
                           "when the joint is held at a limit.")},
    }};
    return table;
}

} // namespace granota::ui
