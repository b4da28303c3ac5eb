#include "ui/fit/fit_degree_box.h"

namespace granota::ui {

QAbstractSpinBox::StepEnabled FitDegreeBox::stepEnabled() const
{
    StepEnabled e = QSpinBox::stepEnabled();
    if (isEnabled() && !isReadOnly() && refused)
        e |= StepUpEnabled;
    return e;
}

void FitDegreeBox::stepBy(int steps)
{
    if (steps > 0 && value() + steps > maximum() && refused)
        refused(value() + steps);
    QSpinBox::stepBy(steps);
}

QValidator::State FitDegreeBox::validate(QString& input, int& pos) const
{
    bool ok = false;
    const int v = input.trimmed().toInt(&ok);
    if (ok && v > maximum()) {
        if (refused)
            refused(v);
        return QValidator::Invalid;
    }
    return QSpinBox::validate(input, pos);
}

} // namespace granota::ui
