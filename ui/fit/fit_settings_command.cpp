#include "ui/fit/fit_settings_command.h"

namespace granota::ui {

FitSettingsCommand::FitSettingsCommand(std::function<void(const FitSettings&)> apply, FitSettings before,
                                       FitSettings after, const QString& text, int field, QUndoCommand* parent)
    : QUndoCommand(text, parent), m_apply(std::move(apply)), m_before(before), m_after(after), m_field(field)
{
}

void FitSettingsCommand::undo() { m_apply(m_before); }
void FitSettingsCommand::redo() { m_apply(m_after); }

bool FitSettingsCommand::mergeWith(const QUndoCommand* other)
{
    const auto* next = dynamic_cast<const FitSettingsCommand*>(other);
    if (!next || next->m_field != m_field || m_field < 0)
        return false;
    m_after = next->m_after;
    if (m_after == m_before)
        setObsolete(true); // back where it started: no step at all
    return true;
}

} // namespace granota::ui
