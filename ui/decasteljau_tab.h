#pragma once
/// \file decasteljau_tab.h
/// The De Casteljau tab (SPEC §1).

#include "ui/tab_page.h"

class QUndoStack;

namespace granota::ui {

class CurveCanvas;

class DeCasteljauTab : public TabPage {
    Q_OBJECT
public:
    explicit DeCasteljauTab(QWidget* parent = nullptr);

    QString key() const override { return QStringLiteral("decasteljau"); }
    QString title() const override { return tr("De Casteljau"); }
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
