#include "ui/common/point_commands.h"

#include "ui/common/point_editor.h"

namespace granota::ui {

PointsCommand::PointsCommand(PointEditor* editor, std::vector<Point> before, std::vector<Point> after,
                             const QString& text)
    : QUndoCommand(text), m_editor(editor), m_before(std::move(before)), m_after(std::move(after))
{
}

void PointsCommand::undo() { m_editor->applyPoints(m_before); }
void PointsCommand::redo() { m_editor->applyPoints(m_after); }

} // namespace granota::ui
