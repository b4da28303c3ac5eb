#include "ui/decasteljau_tab.h"

#include "ui/curve_canvas.h"

#include <QUndoStack>
#include <QVBoxLayout>

namespace granota::ui {

DeCasteljauTab::DeCasteljauTab(QWidget* parent) : TabPage(parent), m_undo(new QUndoStack(this)), m_canvas(new CurveCanvas(this))
{
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_canvas);
    retranslate();
}

void DeCasteljauTab::retranslate() {}
QJsonObject DeCasteljauTab::saveState() const { return {}; }
bool DeCasteljauTab::loadState(const QJsonObject&, QString*) { return true; }
bool DeCasteljauTab::loadExample(const granota::WorkedExample&) { return false; }
Drawable* DeCasteljauTab::exportView() { return m_canvas; }
QString DeCasteljauTab::csv() const { return {}; }
QString DeCasteljauTab::tikz() const { return {}; }

} // namespace granota::ui
