#include "ui/shell/thesis_figures_dialog.h"

#include "core/io/thesis_figures.h"
#include "core/softbody/recorded_run.h"
#include "ui/frog/frog_canvas.h"
#include "ui/frog/frog_tab.h"
#include "ui/shell/main_window.h"
#include "ui/files/file_dialogs.h"
#include "ui/shell/thesis_figure_export.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QEvent>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QMessageBox>
#include <QPushButton>
#include <QVBoxLayout>

namespace granota::ui {

namespace {
const ThesisFigure* figureAt(int row)
{
    const auto& figures = thesisFigures();
    return row >= 0 && row < static_cast<int>(figures.size()) ? &figures[static_cast<std::size_t>(row)] : nullptr;
}
} // namespace

ThesisFiguresDialog::ThesisFiguresDialog(MainWindow* window)
    : QDialog(window), m_window(window), m_list(new QListWidget(this)), m_variants(new QComboBox(this)),
      m_variantLabel(new QLabel(this)), m_note(new QLabel(this)), m_show(new QPushButton(this)), m_export(new QPushButton(this)),
      m_close(new QPushButton(this))
{
    setObjectName(QStringLiteral("thesisFigures"));
    m_list->setObjectName(QStringLiteral("figureList"));
    m_variants->setObjectName(QStringLiteral("figureVariant"));
    m_note->setWordWrap(true);
    m_note->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_note->setMinimumHeight(m_note->fontMetrics().lineSpacing() * 4);
    m_list->setWordWrap(true);
    for (std::size_t i = 0; i < thesisFigures().size(); ++i)
        m_list->addItem(QString());

    auto* variantRow = new QHBoxLayout;
    variantRow->addWidget(m_variantLabel);
    variantRow->addWidget(m_variants, 1);
    m_variantLabel->setBuddy(m_variants);
    auto* buttons = new QDialogButtonBox(this);
    buttons->addButton(m_show, QDialogButtonBox::AcceptRole);
    buttons->addButton(m_export, QDialogButtonBox::ActionRole);
    buttons->addButton(m_close, QDialogButtonBox::RejectRole);
    m_show->setDefault(true);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_list, 1);
    layout->addLayout(variantRow);
    layout->addWidget(m_note);
    layout->addWidget(buttons);

    connect(m_list, &QListWidget::currentRowChanged, this, &ThesisFiguresDialog::figureChosen);
    connect(m_list, &QListWidget::itemActivated, this, [this] { showChosen(); });
    connect(m_variants, qOverload<int>(&QComboBox::currentIndexChanged), this, &ThesisFiguresDialog::variantChosen);
    connect(m_show, &QPushButton::clicked, this, [this] { showChosen(); });
    connect(m_export, &QPushButton::clicked, this, &ThesisFiguresDialog::exportChosen);
    connect(m_close, &QPushButton::clicked, this, &QDialog::reject);

    retranslate();
    m_list->setCurrentRow(0);
    // Fits a 800×600 projector with room for the window's frame.
    resize(560, 460);
}

void ThesisFiguresDialog::retranslate()
{
    setWindowTitle(tr("Thesis figures"));
    m_variantLabel->setText(tr("&Variant:"));
    m_show->setText(tr("&Show"));
    m_export->setText(tr("&Export…"));
    m_close->setText(tr("Close"));
    for (int row = 0; row < m_list->count(); ++row)
        m_list->item(row)->setText(thesisFigureCaption(*figureAt(row)));
    figureChosen(m_list->currentRow());
}

void ThesisFiguresDialog::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QDialog::changeEvent(event);
}

void ThesisFiguresDialog::figureChosen(int row)
{
    const ThesisFigure* figure = figureAt(row);
    if (!figure)
        return;
    const int keep = m_variants->count() == static_cast<int>(figure->variants.size()) ? m_variants->currentIndex() : 0;
    const QSignalBlocker block(m_variants);
    m_variants->clear();
    for (const FigureVariant& v : figure->variants)
        m_variants->addItem(thesisFigureVariantLabel(v), QString::fromStdString(v.name));
    m_variants->setCurrentIndex(std::max(0, keep));
    m_variants->setEnabled(figure->variants.size() > 1);
    variantChosen(m_variants->currentIndex());
}

void ThesisFiguresDialog::variantChosen(int index)
{
    const ThesisFigure* figure = figureAt(m_list->currentRow());
    if (!figure || index < 0 || index >= static_cast<int>(figure->variants.size()))
        return;
    QString note = thesisFigureNote(figure->variants[static_cast<std::size_t>(index)]);
    if (!figure->art.empty())
        note += (note.isEmpty() ? QString() : QStringLiteral(" ")) + tr("It has no tab of its own: Export… writes it.");
    m_note->setText(note);
    m_show->setEnabled(figure->art.empty());
}

bool ThesisFiguresDialog::showChosen()
{
    const ThesisFigure* figure = figureAt(m_list->currentRow());
    if (!figure || !figure->art.empty())
        return false;
    const FigureVariant& variant = figure->variants[static_cast<std::size_t>(std::max(0, m_variants->currentIndex()))];
    // The Frog tab's history starts again with a scene set from outside: a recorded run is
    // not thrown away without asking.
    if (!figure->scene.empty()) {
        const RecordedRun* run = m_window->frogTab()->canvas()->frogRun()->recorded();
        const long steps = run ? run->recordedSteps() : 0;
        if (steps > 0 &&
            QMessageBox::question(this, tr("Thesis figures"),
                                  tr("Showing Fig %1 replaces the Frog tab's run of %n step(s), which cannot be undone. Show it?",
                                     nullptr, static_cast<int>(steps))
                                      .arg(QString::fromStdString(figure->number)),
                                  QMessageBox::Yes | QMessageBox::Cancel, QMessageBox::Cancel) != QMessageBox::Yes)
            return false;
    }
    QString error;
    if (!showThesisFigure(*m_window, *figure, variant, true, &error)) {
        QMessageBox::warning(this, tr("Thesis figures"), error);
        return false;
    }
    return true;
}

void ThesisFiguresDialog::exportChosen()
{
    const ThesisFigure* figure = figureAt(m_list->currentRow());
    if (!figure)
        return;
    if (figure->art.empty() && !showChosen())
        return;
    const QString name = QStringLiteral("fig-%1.svg").arg(QString::fromStdString(figure->number));
    const QString file = saveFileName(this, tr("Export figure"), name, tr("Figures (*.svg *.pdf *.png *.tex *.csv)"));
    if (file.isEmpty())
        return;
    const QString format = QFileInfo(file).suffix().toLower();
    const QString error = exportThesisFigure(*m_window, *figure, format, file, QSize(), 300);
    if (!error.isEmpty())
        QMessageBox::warning(this, tr("Export figure"), error);
}

} // namespace granota::ui
