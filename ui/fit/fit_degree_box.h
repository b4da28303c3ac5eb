#pragma once
/// \file fit_degree_box.h
/// The Fitting tab's degree spin box: it refuses n > k (or n > kMaxFitDegree) with a reason
/// instead of silently (docs/tabs.md). Up stays enabled at the maximum (arrow, key, wheel),
/// so that asking for more is answered with the reason rather than a greyed-out arrow that
/// does nothing; a typed degree beyond it is refused with the reason too.

#include <QSpinBox>

#include <functional>

namespace granota::ui {

class FitDegreeBox : public QSpinBox {
public:
    using QSpinBox::QSpinBox;
    std::function<void(int)> refused; ///< called with the degree that was asked for

    StepEnabled stepEnabled() const override;
    void stepBy(int steps) override;

protected:
    QValidator::State validate(QString& input, int& pos) const override;
};

} // namespace granota::ui
