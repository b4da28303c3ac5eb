#pragma once
/// \file decimal_spin_box.h
/// A QDoubleSpinBox for the interface language: it shows the decimal sign of the language
/// in use (a comma in Catalan) and reads what a person types there, a comma or a point.
/// Qt's own spin box takes a typed point in Catalan for the group separator, so "1.5"
/// would become 15.

#include <QDoubleSpinBox>

namespace granota::ui {

class DecimalSpinBox : public QDoubleSpinBox {
public:
    using QDoubleSpinBox::QDoubleSpinBox;

    QValidator::State validate(QString& text, int& pos) const override;
    double valueFromText(const QString& text) const override;
    void fixup(QString& text) const override;

protected:
    /// `text` with a typed point read as the locale's decimal sign.
    QString withLocaleDecimal(const QString& text) const;
};

} // namespace granota::ui
