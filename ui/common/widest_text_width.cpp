#include "ui/common/widest_text_width.h"

#include <QAbstractButton>
#include <QEvent>

#include <algorithm>

namespace granota::ui {

namespace {

/// Sets the button's minimum width from its texts, now and whenever its font or style changes.
class WidestTextWidth : public QObject {
public:
    static constexpr const char* kName = "granotaWidestTextWidth";

    explicit WidestTextWidth(QAbstractButton* button) : QObject(button), m_button(button)
    {
        setObjectName(QString::fromLatin1(kName));
        button->installEventFilter(this);
    }

    void setTexts(const QStringList& texts)
    {
        m_texts = texts;
        apply();
    }

protected:
    bool eventFilter(QObject* watched, QEvent* event) override
    {
        if (watched == m_button && (event->type() == QEvent::FontChange || event->type() == QEvent::StyleChange))
            apply();
        return QObject::eventFilter(watched, event);
    }

private:
    void apply()
    {
        if (m_applying)
            return;
        m_applying = true;
        const QString shown = m_button->text();
        const bool updates = m_button->updatesEnabled();
        m_button->setUpdatesEnabled(false);
        int widest = 0;
        for (const QString& text : m_texts) {
            m_button->setText(text);
            widest = std::max(widest, m_button->sizeHint().width());
        }
        m_button->setText(shown);
        m_button->setUpdatesEnabled(updates);
        m_button->setMinimumWidth(widest);
        m_applying = false;
    }

    QAbstractButton* m_button;
    QStringList m_texts;
    bool m_applying = false;
};

} // namespace

void keepWidestTextWidth(QAbstractButton* button, const QStringList& texts)
{
    // No Q_OBJECT: found by its name, which only this class gives.
    auto* keeper = static_cast<WidestTextWidth*>(
        button->findChild<QObject*>(QString::fromLatin1(WidestTextWidth::kName), Qt::FindDirectChildrenOnly));
    if (!keeper)
        keeper = new WidestTextWidth(button);
    keeper->setTexts(texts);
}

} // namespace granota::ui
