#include "ui/catmull_rom_tab.h"

#include "ui/curve_canvas.h"

#include <QUndoStack>
#include <QVBoxLayout>

namespace granota::ui {

CatmullRomTab::CatmullRomTab(QWidget* parent) : TabPage(parent), m_undo(new QUndoStack(this)), m_canvas(new CurveCanvas(this))
{
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_canvas);
    retranslate();
}

void CatmullRomTab::retranslate() {}
QJsonObject CatmullRomTab::saveState() const { return {}; }
bool CatmullRomTab::loadState(const QJsonObject&, QString*) { return true; }
bool CatmullRomTab::loadExample(const granota::WorkedExample&) { return false; }
Drawable* CatmullRomTab::exportView() { return m_canvas; }
QString CatmullRomTab::csv() const { return {}; }
QString CatmullRomTab::tikz() const { return {}; }

} // namespace granota::ui
