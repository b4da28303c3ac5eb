#pragma once
/// \file point_commands.h
/// The undo step of every point edit: the points before and after (a handful of points, so
/// storing both is simpler and safer than inverse operations). Successive arrow-key nudges of
/// the same point merge into one step, as a drag is one step (docs/tabs.md); nudged back to
/// where they started, they leave no step at all.

#include "core/base/vec2.h"

#include <QUndoCommand>

#include <vector>

namespace granota::ui {

class PointEditor;

class PointsCommand : public QUndoCommand {
public:
    /// `nudged` ≥ 0: the step is an arrow-key nudge of that point, merged with the next nudge
    /// of the same point.
    /// `nudged` of a keyboard mold of the curve (the De Casteljau tab's Alt+arrows): no control
    /// point has this index, so its run merges only with itself.
    static constexpr int kCurveNudge = 1 << 20;

    PointsCommand(PointEditor* editor, std::vector<Point> before, std::vector<Point> after, const QString& text, int nudged = -1);
    void undo() override;
    void redo() override;
    int id() const override;
    bool mergeWith(const QUndoCommand* other) override;

private:
    PointEditor* m_editor;
    std::vector<Point> m_before, m_after;
    int m_nudged;
};

} // namespace granota::ui
