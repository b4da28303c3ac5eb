#pragma once
/// \file bernstein_tab.h
/// The Bernstein tab (SPEC §1).

#include "ui/tab_page.h"

class QUndoStack;

namespace granota::ui {

class CurveCanvas;
class DeCasteljauTab;

class BernsteinTab : public TabPage {
    Q_OBJECT
public:
    /// Shares the control points and the parameter t of the De Casteljau tab (SPEC §1.2).
    explicit BernsteinTab(DeCasteljauTab* deCasteljau, QWidget* parent = nullptr);

    QString key() const override { return QStringLiteral("bernstein"); }
    QString title() const override { return tr("Bernstein"); }
    void retranslate() override;
    QJsonObject saveState() const override;
    bool loadState(const QJsonObject& state, QString* error) override;
    bool loadExample(const granota::WorkedExample& example) override;
    QUndoStack* undoStack() const override { return m_undo; }
    Drawable* exportView() override;
    QString csv() const override;
    QString tikz() const override;

private:
    DeCasteljauTab* m_deCasteljau;
    QUndoStack* m_undo;
    CurveCanvas* m_canvas;
};

} // namespace granota::ui
