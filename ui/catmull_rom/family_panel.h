#pragma once
/// \file family_panel.h
/// The Catmull-Rom tab's family box (issue 37): the family selector (curve_family.h) on top,
/// and under it the controls of the chosen family — the cardinal tension c, the T, C, B
/// sliders of Kochanek–Bartels for the selected point or for all, the Hermite family's reset
/// to the Catmull-Rom tangents. Every slider moves in exact steps of 1/20 in [−1, 1]. It only
/// shows settings and reports what the user asks for; the tab turns each request into an undo
/// step.

#include "ui/catmull_rom/catmull_rom_settings.h"

#include <QGroupBox>

#include <array>

class QCheckBox;
class QComboBox;
class QLabel;
class QPushButton;
class QSlider;

namespace granota::ui {

class FamilyPanel : public QGroupBox {
    Q_OBJECT
public:
    explicit FamilyPanel(QWidget* parent = nullptr);

    /// Shows `settings` (T, C, B of `selectedPoint`, −1 for none) without emitting anything.
    void showSettings(const CatmullRomSettings& settings, int selectedPoint);
    void retranslate();
    /// T, C, B apply to every point (or no point is selected).
    bool allKnots() const;

    QComboBox* familyCombo() const { return m_familyCombo; }
    QSlider* cardinalSlider() const { return m_cardinalSlider; }
    /// 0: T, 1: C, 2: B.
    QSlider* tcbSlider(int which) const { return m_tcbSliders[static_cast<std::size_t>(which)]; }
    QCheckBox* allKnotsCheck() const { return m_allKnots; }

signals:
    void familyChosen(granota::ui::CurveFamily family);
    void cardinalTensionChosen(granota::Rational c);
    /// which: 0 T, 1 C, 2 B.
    void tcbChosen(int which, granota::Rational value);
    void resetTangentsAsked();

private:
    QLabel* m_familyLabel = nullptr;
    QComboBox* m_familyCombo = nullptr;
    QLabel* m_ruleLabel = nullptr;
    QLabel* m_cardinalLabel = nullptr;
    QSlider* m_cardinalSlider = nullptr;
    QLabel* m_knotLabel = nullptr;
    QCheckBox* m_allKnots = nullptr;
    std::array<QLabel*, 3> m_tcbLabels{};
    std::array<QSlider*, 3> m_tcbSliders{};
    QPushButton* m_resetTangents = nullptr;
    CatmullRomSettings m_shown;
    int m_selectedPoint = -1;
    bool m_showing = false;
};

} // namespace granota::ui
