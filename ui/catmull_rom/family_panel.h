#pragma once
/// \file family_panel.h
/// The Catmull-Rom tab's family box (issue 37): the family selector (curve_family.h) on top,
/// and under it the controls of the chosen family. It only shows settings and reports what
/// the user asks for; the tab turns each request into one undo step.

#include "ui/catmull_rom/catmull_rom_settings.h"

#include <QGroupBox>

class QComboBox;
class QLabel;

namespace granota::ui {

class FamilyPanel : public QGroupBox {
    Q_OBJECT
public:
    explicit FamilyPanel(QWidget* parent = nullptr);

    /// Shows `settings` without emitting anything.
    void showSettings(const CatmullRomSettings& settings);
    void retranslate();

    QComboBox* familyCombo() const { return m_familyCombo; }

signals:
    void familyChosen(granota::ui::CurveFamily family);

private:
    QLabel* m_familyLabel = nullptr;
    QComboBox* m_familyCombo = nullptr;
    bool m_showing = false;
};

} // namespace granota::ui
