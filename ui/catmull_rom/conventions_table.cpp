#include "ui/catmull_rom/conventions_table.h"

#include "core/curves/splines/cardinal_spline.h"
#include "ui/common/number_text.h"

#include <QHeaderView>

namespace granota::ui {

std::vector<TensionConvention> tensionConventions(const Rational& tau)
{
    const Rational oneMinusTwoTau = tauToCardinal(tau); // s, t and T alike: 1 − 2τ (cardinal_spline.h)
    std::optional<Rational> primer;
    if (tau > 0)
        primer = Rational(1) / (Rational(2) * tau);
    return {
        {ConventionsTable::tr("Granota, the thesis (Def 2.8)"), QStringLiteral("τ"), QStringLiteral("τ"), tau},
        {ConventionsTable::tr("Processing"), QStringLiteral("curveTightness(s)"), QStringLiteral("s = 1 − 2τ"), oneMinusTwoTau},
        {ConventionsTable::tr("Primer on Bézier curves"), QStringLiteral("τₚ"), QStringLiteral("τₚ = 1/(2τ)"), primer},
        {ConventionsTable::tr("d3-shape"), QStringLiteral("curveCardinal.tension(t)"), QStringLiteral("t = 1 − 2τ"),
         oneMinusTwoTau},
        {ConventionsTable::tr("Kochanek–Bartels (C = B = 0)"), QStringLiteral("T"), QStringLiteral("T = 1 − 2τ"), oneMinusTwoTau},
    };
}

ConventionsTable::ConventionsTable(QWidget* parent) : QTableWidget(parent)
{
    setColumnCount(4);
    setEditTriggers(QAbstractItemView::NoEditTriggers);
    verticalHeader()->hide();
    horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    horizontalHeader()->setStretchLastSection(true);
    setWordWrap(false);
}

void ConventionsTable::showTau(const Rational& tau)
{
    m_tau = tau;
    const auto rows = tensionConventions(tau);
    setRowCount(static_cast<int>(rows.size()));
    for (int r = 0; r < static_cast<int>(rows.size()); ++r) {
        const TensionConvention& c = rows[static_cast<std::size_t>(r)];
        setItem(r, 0, new QTableWidgetItem(c.source));
        setItem(r, 1, new QTableWidgetItem(c.parameter));
        setItem(r, 2, new QTableWidgetItem(c.fromTau));
        auto* value = new QTableWidgetItem(c.value ? displayText(toString(*c.value)) : tr("none (τ ≤ 0)"));
        value->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        setItem(r, 3, value);
    }
}

void ConventionsTable::retranslate()
{
    setHorizontalHeaderLabels({tr("Source"), tr("Parameter"), tr("From τ"), tr("Value")});
    setToolTip(tr("The same Catmull-Rom tangent τ(qᵢ₊₁ − qᵢ₋₁) in each source's convention, with its value for the "
                  "curve shown: the selected τ, the cardinal c, or T of the selected point."));
    setAccessibleName(tr("Tension conventions"));
    showTau(m_tau);
}

} // namespace granota::ui
