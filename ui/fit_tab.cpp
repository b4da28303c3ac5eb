#include "ui/fit_tab.h"

#include "ui/curve_canvas.h"

#include <QUndoStack>
#include <QVBoxLayout>

namespace granota::ui {

FitTab::FitTab(QWidget* parent) : TabPage(parent), m_undo(new QUndoStack(this)), m_canvas(new CurveCanvas(this))
{
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_canvas);
    retranslate();
}

void FitTab::retranslate() {}
QJsonObject FitTab::saveState() const { return {}; }
bool FitTab::loadState(const QJsonObject&, QString*) { return true; }
bool FitTab::loadExample(const granota::WorkedExample&) { return false; }
Drawable* FitTab::exportView() { return m_canvas; }
QString FitTab::csv() const { return {}; }
QString FitTab::tikz() const { return {}; }

} // namespace granota::ui
