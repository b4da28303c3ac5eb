#include "ui/bernstein_tab.h"

#include "ui/curve_canvas.h"

#include <QUndoStack>
#include <QVBoxLayout>

namespace granota::ui {

BernsteinTab::BernsteinTab(DeCasteljauTab* deCasteljau, QWidget* parent)
    : TabPage(parent), m_deCasteljau(deCasteljau), m_undo(new QUndoStack(this)), m_canvas(new CurveCanvas(this))
{
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_canvas);
    retranslate();
}

void BernsteinTab::retranslate() {}
QJsonObject BernsteinTab::saveState() const { return {}; }
bool BernsteinTab::loadState(const QJsonObject&, QString*) { return true; }
bool BernsteinTab::loadExample(const granota::WorkedExample&) { return false; }
Drawable* BernsteinTab::exportView() { return m_canvas; }
QString BernsteinTab::csv() const { return {}; }
QString BernsteinTab::tikz() const { return {}; }

} // namespace granota::ui
