#include "ui/common/decimal_spin_box.h"

namespace granota::ui {

QString DecimalSpinBox::withLocaleDecimal(const QString& text) const
{
    const QString point = locale().decimalPoint();
    if (point == QLatin1String("."))
        return text;
    QString s = text;
    s.replace(QLatin1Char('.'), point);
    return s;
}

QValidator::State DecimalSpinBox::validate(QString& text, int& pos) const
{
    QString s = withLocaleDecimal(text);
    const QValidator::State state = QDoubleSpinBox::validate(s, pos);
    if (state != QValidator::Invalid)
        text = s; // what is accepted is shown with the locale's sign
    return state;
}

double DecimalSpinBox::valueFromText(const QString& text) const { return QDoubleSpinBox::valueFromText(withLocaleDecimal(text)); }

void DecimalSpinBox::fixup(QString& text) const
{
    text = withLocaleDecimal(text);
    QDoubleSpinBox::fixup(text);
}

} // namespace granota::ui
