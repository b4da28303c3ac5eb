#include "ui/main_window.h"

#include <QLabel>
#include <QTabWidget>

namespace granota::ui {

namespace {
const char* const kTabKeys[] = {"decasteljau", "bernstein", "fit", "catmull-rom", "frog"};
}

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent), m_tabs(new QTabWidget(this))
{
    for (int i = 0; i < 5; ++i) {
        auto* page = new QLabel(this);
        page->setAlignment(Qt::AlignCenter);
        m_tabs->addTab(page, QString());
    }
    setCentralWidget(m_tabs);
    resize(1280, 800);
    retranslate();
}

bool MainWindow::showTab(const QString& key)
{
    for (int i = 0; i < 5; ++i)
        if (key == QLatin1String(kTabKeys[i])) {
            m_tabs->setCurrentIndex(i);
            return true;
        }
    return false;
}

void MainWindow::retranslate()
{
    setWindowTitle(tr("Granota"));
    const QString titles[] = {tr("De Casteljau"), tr("Bernstein"), tr("Fitting"), tr("Catmull-Rom"), tr("Frog")};
    const QString refs[] = {tr("§2.1.1, Def 2.4"), tr("§2.1.2, Def 2.5"), tr("§2.1.3, Lemma 2.2"),
                            tr("§2.2, Def 2.10"), tr("Chapter 4, Annex II")};
    for (int i = 0; i < 5; ++i) {
        m_tabs->setTabText(i, titles[i]);
        if (auto* label = qobject_cast<QLabel*>(m_tabs->widget(i)))
            label->setText(QStringLiteral("%1\n%2").arg(titles[i], refs[i]));
    }
}

} // namespace granota::ui
