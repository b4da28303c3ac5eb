#pragma once
/// \file catmull_rom_commands.h
/// The undo step of the Catmull-Rom tab's settings (tensions added, removed or dragged with
/// the slider, mode, spacing, comparisons): the settings before and after. Consecutive slider
/// moves of the same τ merge into one step.

#include "ui/catmull_rom/catmull_rom_settings.h"

#include <QUndoCommand>

#include <functional>

namespace granota::ui {

class CatmullRomSettingsCommand : public QUndoCommand {
public:
    using Apply = std::function<void(const CatmullRomSettings&)>;
    /// `mergeable`: a slider move, merged with the previous slider move of the same τ.
    CatmullRomSettingsCommand(Apply apply, CatmullRomSettings before, CatmullRomSettings after, const QString& text,
                              bool mergeable = false);
    void undo() override;
    void redo() override;
    int id() const override;
    bool mergeWith(const QUndoCommand* other) override;

private:
    Apply m_apply;
    CatmullRomSettings m_before, m_after;
    bool m_mergeable;
};

} // namespace granota::ui
