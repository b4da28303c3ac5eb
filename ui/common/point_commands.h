#pragma once
/// \file point_commands.h
/// The undo step of every point edit: the points before and after (a handful of points, so
/// storing both is simpler and safer than inverse operations). Successive arrow-key nudges of
/// the same point merge into one step, as a drag is one step (docs/tabs.md); nudged back to
/// where they started, they leave no step at all.

#include "core/base/vec2.h"
#include "core/exact/exact_point.h"

#include <QUndoCommand>

#include <vector>

namespace granota::ui {

class PointEditor;

/// The editor's points: the doubles, and index by index their exact forms (exact_point.h).
struct EditedPoints {
    std::vector<Point> points;
    /// One per point, or empty: none has an exact form (a list beyond kExactFormsUpTo points).
    std::vector<ExactPoint> exact;

    /// Point i's exact form (none when the list keeps none).
    const ExactPoint& exactAt(std::size_t i) const;
    /// Edits that keep `exact` in step with `points`.
    void set(std::size_t i, Point p, const ExactPoint& q);
    void insert(std::size_t i, Point p, const ExactPoint& q);
    void erase(std::size_t i);
};
bool operator==(const EditedPoints& a, const EditedPoints& b);
inline bool operator!=(const EditedPoints& a, const EditedPoints& b) { return !(a == b); }

class PointsCommand : public QUndoCommand {
public:
    /// `nudged` ≥ 0: the step is an arrow-key nudge of that point, merged with the next nudge
    /// of the same point.
    /// `nudged` of a keyboard mold of the curve (the De Casteljau tab's Alt+arrows): no control
    /// point has this index, so its run merges only with itself.
    static constexpr int kCurveNudge = 1 << 20;

    PointsCommand(PointEditor* editor, EditedPoints before, EditedPoints after, const QString& text, int nudged = -1);
    void undo() override;
    void redo() override;
    int id() const override;
    bool mergeWith(const QUndoCommand* other) override;

private:
    PointEditor* m_editor;
    EditedPoints m_before, m_after;
    int m_nudged;
};

} // namespace granota::ui
