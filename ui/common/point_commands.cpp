#include "ui/common/point_commands.h"

#include "ui/common/point_editor.h"

namespace granota::ui {

namespace {
/// QUndoCommand::id() of a nudge; every other point edit is −1 (never merged).
constexpr int kNudgeCommandId = 0x4e55; // "NU"
} // namespace

PointsCommand::PointsCommand(PointEditor* editor, std::vector<Point> before, std::vector<Point> after, const QString& text,
                             int nudged)
    : QUndoCommand(text), m_editor(editor), m_before(std::move(before)), m_after(std::move(after)), m_nudged(nudged)
{
}

void PointsCommand::undo() { m_editor->applyPoints(m_before); }
void PointsCommand::redo() { m_editor->applyPoints(m_after); }

int PointsCommand::id() const { return m_nudged >= 0 ? kNudgeCommandId : -1; }

bool PointsCommand::mergeWith(const QUndoCommand* other)
{
    const auto* next = dynamic_cast<const PointsCommand*>(other);
    if (!next || next->m_editor != m_editor || next->m_nudged != m_nudged || m_nudged < 0 || next->m_before != m_after)
        return false;
    m_after = next->m_after;
    if (m_after == m_before)
        setObsolete(true); // nudged back where it started: no step at all
    return true;
}

} // namespace granota::ui
