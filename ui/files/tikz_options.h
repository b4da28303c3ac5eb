#pragma once
/// \file tikz_options.h
/// What a teacher chooses for a TikZ export (File ▸ Export ▸ TikZ, docs/tabs.md): the
/// picture's width, the height it may not pass, and axes with tick labels and a grid.
/// The defaults fit a beamer frame (4:3, default theme), whose text is 10.80 cm (307.29 pt)
/// wide and whose page is 9.63 cm tall, with a frame title above the picture and the
/// navigation bar below it (measured with pdflatex; test_gui_tikz_latex checks it). The last
/// choice is kept in the settings.

namespace granota::ui {

struct TikzOptions {
    /// 10 cm: 0.8 cm less than a beamer frame's text width (10.80 cm), so a picture in a
    /// frame never overflows, and well inside an article's 12.13 cm.
    static constexpr double kDefaultWidthCm = 10.0;
    /// 6.5 cm: under a beamer frame's title the content starts 8.60 cm above the page's
    /// foot, about 8.1 cm above its navigation bar: room for a line of text under the picture.
    static constexpr double kDefaultMaxHeightCm = 6.5;
    /// The range the export dialog offers for both sizes.
    static constexpr double kMinCm = 2.0;
    static constexpr double kMaxCm = 40.0;

    /// The picture's width, labels included; a picture taller than maxHeightCm is made
    /// narrower until it is that tall.
    double widthCm = kDefaultWidthCm;
    double maxHeightCm = kDefaultMaxHeightCm;
    /// Axes with ticks and tick labels at round values, and a light grid at those values.
    bool axes = false;
    bool grid = false;

    /// The last choice the export dialog kept (QSettings "tikz/…"), or the defaults; sizes
    /// outside [kMinCm, kMaxCm] are brought into it.
    static TikzOptions load();
    void save() const;
};

} // namespace granota::ui
