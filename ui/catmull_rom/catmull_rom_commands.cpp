#include "ui/catmull_rom/catmull_rom_commands.h"

namespace granota::ui {

namespace {
constexpr int kSliderMergeId = 0x43520001; ///< "CR" + 1: slider moves of the Catmull-Rom tab
}

CatmullRomSettingsCommand::CatmullRomSettingsCommand(Apply apply, CatmullRomSettings before, CatmullRomSettings after,
                                                     const QString& text, bool mergeable)
    : QUndoCommand(text), m_apply(std::move(apply)), m_before(std::move(before)), m_after(std::move(after)),
      m_mergeable(mergeable)
{
}

void CatmullRomSettingsCommand::undo() { m_apply(m_before); }
void CatmullRomSettingsCommand::redo() { m_apply(m_after); }

int CatmullRomSettingsCommand::id() const { return m_mergeable ? kSliderMergeId : -1; }

bool CatmullRomSettingsCommand::mergeWith(const QUndoCommand* other)
{
    const auto* o = dynamic_cast<const CatmullRomSettingsCommand*>(other);
    if (!o || !o->m_mergeable || o->m_after.selectedTau != m_after.selectedTau ||
        o->m_after.taus.size() != m_after.taus.size())
        return false;
    m_after = o->m_after;
    return true;
}

} // namespace granota::ui
