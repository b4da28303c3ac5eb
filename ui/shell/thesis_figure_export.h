#pragma once
/// \file thesis_figure_export.h
/// A thesis figure (core/io/thesis_figures.h) made real: the tab put in the figure's state,
/// and the figure's view alone exported as SVG, PDF, PNG, TikZ or CSV with the screen's own
/// drawing code (docs/thesis-figures.md). Help ▸ Thesis figures and `granota --figure N
/// --export FILE` both come here.

#include <QJsonObject>
#include <QSize>
#include <QString>

namespace granota {
struct ThesisFigure;
struct FigureVariant;
} // namespace granota

namespace granota::ui {

class MainWindow;
class TabPage;

/// The tab state that draws `figure` as `variant` for `page` (the figure's tab), from the
/// state the tab is in after loading the figure's worked example: the figure's settings,
/// then the variant's, over it. A frog figure's state: its scene on the seed solver, no
/// overlays, paused after its steps, with the variant's input events.
QJsonObject thesisFigureState(const TabPage& page, const ThesisFigure& figure, const FigureVariant& variant);

/// Shows `figure` as `variant` in `window`: its tab, in the figure's state. `undoable`: one
/// step on the tab's history ("Fig 2.7"), for a window the user works in; the Frog tab has
/// no such step (a scene set from outside starts a history). False with a translated
/// message. An art figure (4.11, 4.12) has no tab state: nothing changes, true.
bool showThesisFigure(MainWindow& window, const ThesisFigure& figure, const FigureVariant& variant, bool undoable,
                      QString* error);

/// Exports the figure shown by showThesisFigure(): `format` svg, pdf, png (at `dpi`), tex
/// (TikZ) or csv, the view alone drawn at `size` (logical pixels; PNG's pixels are size ×
/// dpi/96; an empty size: the view's own). Empty, or a translated message.
QString exportThesisFigure(MainWindow& window, const ThesisFigure& figure, const QString& format, const QString& file, QSize size,
                           int dpi);

/// The export formats, as `--export`'s file suffixes: svg, pdf, png, tex, csv.
QStringList thesisFigureFormats();

/// "Fig 2.7 — caption", in the current language (the gallery, --list-figures).
QString thesisFigureCaption(const ThesisFigure& figure);
/// The variant's name as the gallery shows it, in the current language ("as the thesis
/// computed it" for `thesis`); the command line uses the names themselves.
QString thesisFigureVariantLabel(const FigureVariant& variant);
/// The variant's note in the current language (empty for a figure with one way to draw it).
QString thesisFigureNote(const FigureVariant& variant);

} // namespace granota::ui
