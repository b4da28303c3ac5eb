#pragma once
/// \file plot_tick_room.h
/// Tick labels are never cut by the edge of their plot. QCustomPlot centres a horizontal
/// axis's tick labels on their ticks, so the label of a tick at the left end of the axis
/// ("−0,5" when the range starts there) reaches half its width into the left margin; the
/// automatic margins make room for the vertical axis's own labels and title (and are at least
/// 15 px), not for that half. With a large font (presentation mode) and a vertical axis that
/// takes little room, the label's start — its minus sign — fell outside the widget. The same
/// holds at the right end, and for a vertical axis's top and bottom labels. Every plot of the
/// application has this, the CLI's report plot too. (The canvases' grid labels are
/// CurveCanvas's: it draws only those wholly inside.)

class QCustomPlot;

namespace granota::ui {

/// Keeps `plot`'s axis rect's minimum margins wide enough, before each replot, for the
/// outermost tick labels of each of its axes; installing it twice is installing it once.
void keepTickLabelsInside(QCustomPlot* plot);

} // namespace granota::ui
