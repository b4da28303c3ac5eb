#include "core/softbody/scenes/scene_texts.h"

#include "core/softbody/scenes/translatable_text.h"

#include <algorithm>

namespace granota {

const std::vector<SceneText>& sceneTexts()
{
    static const std::vector<SceneText> texts = {
        {"polygon", "4.1", QT_TRANSLATE_NOOP("granota::ui::FrogTab", "Polygon and mouse"),
         QT_TRANSLATE_NOOP("granota::ui::FrogTab", "A regular polygon drawn with straight lines; its "
                                                   "radius follows the mouse, r = |mouseY − h/2|.")},
        {"gravity", "4.2", QT_TRANSLATE_NOOP("granota::ui::FrogTab", "Gravity"),
         QT_TRANSLATE_NOOP("granota::ui::FrogTab", "Every vertex falls with constant acceleration "
                                                   "(MRUA) and stops at the edge of the frame.")},
        {"bounce", "4.3", QT_TRANSLATE_NOOP("granota::ui::FrogTab", "Bounce"),
         QT_TRANSLATE_NOOP("granota::ui::FrogTab", "At the frame the velocity turns round and keeps a share f "
                                                   "of itself; a click starts the polygon again at the mouse.")},
        {"springs", "4.4", QT_TRANSLATE_NOOP("granota::ui::FrogTab", "Springs"),
         QT_TRANSLATE_NOOP("granota::ui::FrogTab", "Springs along the edges pull each pair of "
                                                   "neighbours back towards their rest length.")},
        {"area", "4.5", QT_TRANSLATE_NOOP("granota::ui::FrogTab", "Area"),
         QT_TRANSLATE_NOOP("granota::ui::FrogTab", "The area, by the trapezoid rule, is pushed back "
                                                   "towards the target along the edge normals.")},
        {"verlet", "4.6", QT_TRANSLATE_NOOP("granota::ui::FrogTab", "Verlet and grabbing"),
         QT_TRANSLATE_NOOP("granota::ui::FrogTab", "Verlet integration (Def 3.1). Press inside the body "
                                                   "to grab it: every vertex is tied to the mouse.")},
        {"tuned", "4.7", QT_TRANSLATE_NOOP("granota::ui::FrogTab", "Tuned parameters"),
         QT_TRANSLATE_NOOP("granota::ui::FrogTab", "Only the vertices above the grab "
                                                   "point hold on to the mouse.")},
        {"color", "4.8", QT_TRANSLATE_NOOP("granota::ui::FrogTab", "Colour fill"),
         QT_TRANSLATE_NOOP("granota::ui::FrogTab", "The same body, "
                                                   "filled with colour.")},
        {"bezier", "4.9", QT_TRANSLATE_NOOP("granota::ui::FrogTab", "Bézier outline"),
         QT_TRANSLATE_NOOP("granota::ui::FrogTab",
                           "The polygon's vertices are the control points of one Bézier curve, sampled once. "
                           "Beside it, the per-frame least-squares fit that the thesis abandoned, with its cost.")},
        {"bezier-revised", "4.10", QT_TRANSLATE_NOOP("granota::ui::FrogTab", "Revised Bézier"),
         QT_TRANSLATE_NOOP("granota::ui::FrogTab", "Tuned constants, and fixed anchors for "
                                                   "grabbing, on the precomputed Bézier points.")},
        {"catmull-rom", "4.12", QT_TRANSLATE_NOOP("granota::ui::FrogTab", "Catmull-Rom outline"),
         QT_TRANSLATE_NOOP("granota::ui::FrogTab", "The outline is a Catmull-Rom curve through the "
                                                   "vertices (τ = 1/2, Processing's curveVertex).")},
        {"pendulum", "4.13", QT_TRANSLATE_NOOP("granota::ui::FrogTab", "Pendulum"),
         QT_TRANSLATE_NOOP("granota::ui::FrogTab", "A double pendulum hanging from the "
                                                   "mouse; its lengths are restored at once.")},
        {"pendulum-chain", "4.14", QT_TRANSLATE_NOOP("granota::ui::FrogTab", "Chain of joints"),
         QT_TRANSLATE_NOOP("granota::ui::FrogTab", "A chain of joints following its first joint: each joint "
                                                   "is put back at its distance from the previous one.")},
        {"pendulum-limits", "4.15", QT_TRANSLATE_NOOP("granota::ui::FrogTab", "Angle limits"),
         QT_TRANSLATE_NOOP("granota::ui::FrogTab", "A leg: two links with gravity, the frame, "
                                                   "and limits on the angles at its joints.")},
        {"frog", "4.16", QT_TRANSLATE_NOOP("granota::ui::FrogTab", "The frog"),
         QT_TRANSLATE_NOOP("granota::ui::FrogTab", "Body, four legs and head: the "
                                                   "final program of Annex II.")},
        {"obstacles", "5.2.1", QT_TRANSLATE_NOOP("granota::ui::FrogTab", "Obstacles"),
         QT_TRANSLATE_NOOP("granota::ui::FrogTab", "Fixed segments and polygons that the "
                                                   "bodies collide with (future work, §5.2).")},
        {"many-bodies", "5.2.2", QT_TRANSLATE_NOOP("granota::ui::FrogTab", "Many bodies"),
         QT_TRANSLATE_NOOP("granota::ui::FrogTab", "Several bodies collide with each other; a "
                                                   "broad phase keeps the cost close to linear.")},
        {"shapes", "5.2.3", QT_TRANSLATE_NOOP("granota::ui::FrogTab", "Other shapes"),
         QT_TRANSLATE_NOOP("granota::ui::FrogTab", "Bodies that are not regular polygons, kept in "
                                                   "shape by angle constraints between their edges.")},
    };
    return texts;
}

const SceneText* findSceneText(const std::string& name)
{
    const auto& all = sceneTexts();
    const auto it = std::find_if(all.begin(), all.end(), [&](const SceneText& x) { return name == x.name; });
    return it == all.end() ? nullptr : &*it;
}

} // namespace granota
