#include "ui/frog_tab.h"

#include "ui/curve_canvas.h"

#include <QUndoStack>
#include <QVBoxLayout>

namespace granota::ui {

FrogTab::FrogTab(QWidget* parent) : TabPage(parent), m_undo(new QUndoStack(this)), m_canvas(new CurveCanvas(this))
{
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_canvas);
    retranslate();
}

void FrogTab::retranslate() {}
QJsonObject FrogTab::saveState() const { return {}; }
bool FrogTab::loadState(const QJsonObject&, QString*) { return true; }
bool FrogTab::loadExample(const granota::WorkedExample&) { return false; }
Drawable* FrogTab::exportView() { return m_canvas; }
QString FrogTab::csv() const { return {}; }
QString FrogTab::tikz() const { return {}; }
bool FrogTab::setScene(const QString&, QString*) { return true; }
QString FrogTab::exportFrames(const QString&, int) { return {}; }

} // namespace granota::ui
