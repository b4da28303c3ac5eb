#include "ui/common/point_commands.h"

#include "ui/common/point_editor.h"

namespace granota::ui {

namespace {
/// QUndoCommand::id() of a nudge; every other point edit is −1 (never merged).
constexpr int kNudgeCommandId = 0x4e55; // "NU"
} // namespace

bool operator==(const EditedPoints& a, const EditedPoints& b) { return a.points == b.points && a.exact == b.exact; }

const ExactPoint& EditedPoints::exactAt(std::size_t i) const
{
    static const ExactPoint none;
    return exact.size() == points.size() ? exact[i] : none;
}

void EditedPoints::set(std::size_t i, Point p, const ExactPoint& q)
{
    if (exact.size() == points.size())
        exact[i] = q;
    points[i] = p;
}

void EditedPoints::insert(std::size_t i, Point p, const ExactPoint& q)
{
    if (exact.size() == points.size())
        exact.insert(exact.begin() + static_cast<std::ptrdiff_t>(i), q);
    points.insert(points.begin() + static_cast<std::ptrdiff_t>(i), p);
}

void EditedPoints::erase(std::size_t i)
{
    if (exact.size() == points.size())
        exact.erase(exact.begin() + static_cast<std::ptrdiff_t>(i));
    points.erase(points.begin() + static_cast<std::ptrdiff_t>(i));
}

PointsCommand::PointsCommand(PointEditor* editor, EditedPoints before, EditedPoints after, const QString& text, int nudged)
    : QUndoCommand(text), m_editor(editor), m_before(std::move(before)), m_after(std::move(after)), m_nudged(nudged)
{
}

void PointsCommand::undo() { m_editor->applyPoints(m_before.points, m_before.exact); }
void PointsCommand::redo() { m_editor->applyPoints(m_after.points, m_after.exact); }

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
