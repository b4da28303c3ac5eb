#include "ui/catmull_rom/function_data_panel.h"

#include "ui/common/number_text.h"

#include <QCheckBox>
#include <QGridLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPainter>
#include <QPixmap>
#include <QTableWidget>

namespace granota::ui {

namespace {

/// A small square in the curve's colour: the check box names the line of the canvas.
QIcon functionDataSwatch(FunctionDataCurve curve)
{
    QPixmap pixmap(12, 12);
    pixmap.fill(functionDataCurveColour(curve));
    return QIcon(pixmap);
}

} // namespace

FunctionDataPanel::FunctionDataPanel(QWidget* parent) : QWidget(parent)
{
    auto* layout = new QGridLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    for (FunctionDataCurve curve : kFunctionDataCurves) {
        const auto i = static_cast<std::size_t>(curve);
        m_curveChecks[i] = new QCheckBox(this);
        m_curveChecks[i]->setIcon(functionDataSwatch(curve));
        layout->addWidget(m_curveChecks[i], static_cast<int>(i / 2), static_cast<int>(i % 2));
        connect(m_curveChecks[i], &QCheckBox::toggled, this, [this, i](bool on) {
            if (m_showing)
                return;
            FunctionDataSettings after = m_settings;
            after.shown[i] = on;
            emit changeRequested(after, tr("Curves on the data"));
        });
    }
    m_shadeCheck = new QCheckBox(this);
    layout->addWidget(m_shadeCheck, 2, 0, 1, 2);
    connect(m_shadeCheck, &QCheckBox::toggled, this, [this](bool on) {
        if (m_showing)
            return;
        FunctionDataSettings after = m_settings;
        after.shadeOvershoot = on;
        emit changeRequested(after, tr("Overshoot shading"));
    });
    m_error = new QLabel(this);
    m_error->setWordWrap(true);
    m_error->setStyleSheet(QStringLiteral("color: #c62828;"));
    layout->addWidget(m_error, 3, 0, 1, 2);
    m_tableTitle = new QLabel(this);
    m_tableTitle->setWordWrap(true);
    layout->addWidget(m_tableTitle, 4, 0, 1, 2);
    m_table = new QTableWidget(0, 3, this);
    m_table->verticalHeader()->hide();
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionMode(QAbstractItemView::NoSelection);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->setVerticalScrollBarPolicy(Qt::ScrollBarAsNeeded);
    m_tableTitle->setBuddy(m_table);
    layout->addWidget(m_table, 5, 0, 1, 2);
    layout->setColumnStretch(0, 1);
    layout->setColumnStretch(1, 1);
    retranslate();
}

void FunctionDataPanel::showSettings(const FunctionDataSettings& settings, const FunctionDataScene& scene,
                                     const std::vector<Point>& points)
{
    m_showing = true;
    m_settings = settings;
    m_scene = scene;
    m_points = points;
    for (FunctionDataCurve curve : kFunctionDataCurves)
        curveCheck(curve)->setChecked(settings.isShown(curve));
    m_shadeCheck->setChecked(settings.shadeOvershoot);
    m_error->setText(scene.error);
    m_error->setVisible(!scene.error.isEmpty());
    fillTable();
    m_showing = false;
}

void FunctionDataPanel::fillTable()
{
    m_table->setRowCount(static_cast<int>(m_scene.curves.size()));
    int row = 0;
    for (const FunctionDataCurveShape& shape : m_scene.curves) {
        auto* name = new QTableWidgetItem(functionDataSwatch(shape.curve), functionDataCurveLabel(shape.curve));
        auto* amount = new QTableWidgetItem(displaySignificant(shape.largestOvershoot, 4));
        amount->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        QString where = QStringLiteral("—");
        const auto i = static_cast<std::size_t>(shape.largestInterval);
        if (shape.largestInterval >= 0 && i + 1 < m_points.size())
            where = QStringLiteral("[%1, %2]").arg(displayNumber(m_points[i].x), displayNumber(m_points[i + 1].x));
        m_table->setItem(row, 0, name);
        m_table->setItem(row, 1, amount);
        m_table->setItem(row, 2, new QTableWidgetItem(where));
        ++row;
    }
    m_table->setVisible(!m_scene.curves.empty());
    m_tableTitle->setVisible(!m_scene.curves.empty());
}

void FunctionDataPanel::retranslate()
{
    for (FunctionDataCurve curve : kFunctionDataCurves)
        curveCheck(curve)->setText(functionDataCurveLabel(curve));
    m_shadeCheck->setText(tr("Shade the o&vershoot"));
    m_shadeCheck->setToolTip(tr("On each interval [xᵢ, xᵢ₊₁], fill the part of a curve outside the band between yᵢ and "
                                "yᵢ₊₁: where it goes beyond its neighbouring data values."));
    m_tableTitle->setText(tr("Largest overshoot beyond the neighbouring data values:"));
    m_table->setHorizontalHeaderLabels({tr("Curve"), tr("Overshoot"), tr("Interval")});
    m_table->setAccessibleName(tr("Largest overshoot of each curve"));
    fillTable();
}

} // namespace granota::ui
