#include "ui/shell/tikz_options_dialog.h"

#include "ui/common/decimal_spin_box.h"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QVBoxLayout>

namespace granota::ui {

namespace {

DecimalSpinBox* sizeBox(QWidget* parent, double value, const QString& name)
{
    auto* box = new DecimalSpinBox(parent);
    box->setRange(TikzOptions::kMinCm, TikzOptions::kMaxCm);
    box->setDecimals(1);
    box->setSingleStep(0.5);
    box->setSuffix(QStringLiteral(" cm"));
    box->setValue(value);
    box->setObjectName(name);
    return box;
}

} // namespace

TikzOptionsDialog::TikzOptionsDialog(const TikzOptions& options, QWidget* parent) : QDialog(parent)
{
    setWindowTitle(tr("TikZ picture"));
    m_width = sizeBox(this, options.widthCm, QStringLiteral("tikzWidth"));
    m_width->setToolTip(tr("The picture's width on the page, labels included. %1 cm fits a beamer frame.")
                            .arg(QLocale().toString(TikzOptions::kDefaultWidthCm)));
    m_width->setAccessibleName(tr("Width"));
    m_height = sizeBox(this, options.maxHeightCm, QStringLiteral("tikzHeight"));
    m_height->setToolTip(tr("A taller picture is made smaller until it is this tall. %1 cm fits a beamer frame "
                            "with a title.")
                             .arg(QLocale().toString(TikzOptions::kDefaultMaxHeightCm)));
    m_height->setAccessibleName(tr("Height at most"));
    m_axes = new QCheckBox(tr("Axes with tick labels"), this);
    m_axes->setObjectName(QStringLiteral("tikzAxes"));
    m_axes->setChecked(options.axes);
    m_grid = new QCheckBox(tr("Grid"), this);
    m_grid->setObjectName(QStringLiteral("tikzGrid"));
    m_grid->setChecked(options.grid);

    auto* form = new QFormLayout;
    form->addRow(tr("Width:"), m_width);
    form->addRow(tr("Height at most:"), m_height);
    form->addRow(m_axes);
    form->addRow(m_grid);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* note = new QLabel(tr("The defaults fit a beamer frame; the picture needs \\usepackage{tikz}."), this);
    note->setWordWrap(true);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(note);
    layout->addWidget(buttons);
}

TikzOptions TikzOptionsDialog::options() const
{
    TikzOptions o;
    o.widthCm = m_width->value();
    o.maxHeightCm = m_height->value();
    o.axes = m_axes->isChecked();
    o.grid = m_grid->isChecked();
    return o;
}

bool TikzOptionsDialog::ask(QWidget* parent, TikzOptions* options)
{
    TikzOptionsDialog dialog(TikzOptions::load(), parent);
    if (dialog.exec() != QDialog::Accepted)
        return false;
    *options = dialog.options();
    options->save();
    return true;
}

} // namespace granota::ui
