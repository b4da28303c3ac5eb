#include "ui/shell/shortcuts_dialog.h"

#include <QDialogButtonBox>
#include <QPushButton>
#include <QScreen>
#include <QScrollBar>
#include <QTextBrowser>
#include <QVBoxLayout>

#include <algorithm>

namespace granota::ui {

namespace {
/// The widest the two columns are laid out, in average character widths: two tables of
/// keys and their meaning side by side, each line readable without a long wrap.
constexpr int kColumnsWidthInCharacters = 150;
} // namespace

ShortcutsDialog::ShortcutsDialog(QWidget* parent)
    : QDialog(parent), m_browser(new QTextBrowser(this)), m_close(new QPushButton(this))
{
    setObjectName(QStringLiteral("shortcutsDialog"));
    m_browser->setObjectName(QStringLiteral("shortcutsText"));
    m_browser->setOpenLinks(false);
    auto* buttons = new QDialogButtonBox(this);
    buttons->addButton(m_close, QDialogButtonBox::RejectRole);
    m_close->setDefault(true);
    connect(m_close, &QPushButton::clicked, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_browser, 1);
    layout->addWidget(buttons);
}

void ShortcutsDialog::present(const QString& html, const QMargins& frame)
{
    setWindowTitle(tr("Keyboard shortcuts"));
    m_close->setText(tr("&Close"));
    m_browser->setHtml(html);
    // As wide as the columns want and as tall as the text then is, within the screen: the
    // browser scrolls what does not fit.
    const QRect available = screen() ? screen()->availableGeometry() : QRect(0, 0, 800, 600);
    const QRect room = available - frame;
    const int chrome = layout()->contentsMargins().left() + layout()->contentsMargins().right() + 2 * m_browser->frameWidth() +
                       m_browser->verticalScrollBar()->sizeHint().width();
    const int width = std::min(room.width(), fontMetrics().averageCharWidth() * kColumnsWidthInCharacters + chrome);
    m_browser->document()->setTextWidth(width - chrome);
    const int textHeight = static_cast<int>(m_browser->document()->size().height()) + 2 * m_browser->frameWidth();
    const int rest = sizeHint().height() - m_browser->sizeHint().height();
    const int height = std::min(room.height(), textHeight + rest);
    resize(width, height);
    // Over the screen's middle, its frame (where move() puts a window) inside the available area.
    const QSize framed = QSize(width, height).grownBy(frame);
    move(available.left() + (available.width() - framed.width()) / 2,
         available.top() + (available.height() - framed.height()) / 2);
    m_browser->setFocus();
    show();
    raise();
    activateWindow();
}

} // namespace granota::ui
