#pragma once
/// \file fit_tab.h
/// The Fitting tab (SPEC §1).

#include "ui/tab_page.h"

class QUndoStack;

namespace granota::ui {

class CurveCanvas;

class FitTab : public TabPage {
    Q_OBJECT
public:
    explicit FitTab(QWidget* parent = nullptr);

    QString key() const override { return QStringLiteral("fit"); }
    QString title() const override { return tr("Fitting"); }
    void retranslate() override;
    QJsonObject saveState() const override;
    bool loadState(const QJsonObject& state, QString* error) override;
    bool loadExample(const granota::WorkedExample& example) override;
    QUndoStack* undoStack() const override { return m_undo; }
    Drawable* exportView() override;
    QString csv() const override;
    QString tikz() const override;

private:
    QUndoStack* m_undo;
    CurveCanvas* m_canvas;
};

} // namespace granota::ui
