#pragma once
/// \file frog_tab.h
/// The soft-body lab (frog) tab (SPEC §1).

#include "ui/tab_page.h"

class QUndoStack;

namespace granota::ui {

class CurveCanvas;

class FrogTab : public TabPage {
    Q_OBJECT
public:
    explicit FrogTab(QWidget* parent = nullptr);

    QString key() const override { return QStringLiteral("frog"); }
    QString title() const override { return tr("Frog"); }
    void retranslate() override;
    QJsonObject saveState() const override;
    bool loadState(const QJsonObject& state, QString* error) override;
    bool loadExample(const granota::WorkedExample& example) override;
    QUndoStack* undoStack() const override { return m_undo; }
    Drawable* exportView() override;
    QString csv() const override;
    QString tikz() const override;

    /// Opens scene `name` of SPEC §1.5 (`--scene`). False with a message for an unknown name.
    bool setScene(const QString& name, QString* error);
    /// Writes `frames` frames of the running scene as frame_0000.png … into `directory`,
    /// stepping the simulation at the canvas's fixed step. Empty on success, else a message.
    QString exportFrames(const QString& directory, int frames);

private:
    QUndoStack* m_undo;
    CurveCanvas* m_canvas;
};

} // namespace granota::ui
