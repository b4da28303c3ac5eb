#pragma once
/// \file point_commands.h
/// The undo step of every point edit: the points before and after (a handful of points, so
/// storing both is simpler and safer than inverse operations).

#include "core/base/vec2.h"

#include <QUndoCommand>

#include <vector>

namespace granota::ui {

class PointEditor;

class PointsCommand : public QUndoCommand {
public:
    PointsCommand(PointEditor* editor, std::vector<Point> before, std::vector<Point> after, const QString& text);
    void undo() override;
    void redo() override;

private:
    PointEditor* m_editor;
    std::vector<Point> m_before, m_after;
};

} // namespace granota::ui
