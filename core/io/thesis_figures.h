#pragma once
/// \file thesis_figures.h
/// The thesis's 23 figures (Fig 2.1–2.10, 4.1–4.13) as data: resources/figures/thesis_figures.json,
/// compiled into the core as the worked examples are. Each figure names the tab that draws it
/// and the state that tab must be in — the worked example it loads, then the settings over it
/// — or the scene, solver and steps of the Frog tab; a figure the thesis computed otherwise
/// than it defines has variants (`definition`, the default, and `thesis`). The GUI's
/// Help ▸ Thesis figures and `granota --figure N --export FILE` put a tab in that state
/// (ui/shell/thesis_figure_export.h); docs/thesis-figures.md lists them.

#include "core/io/json.h"

#include <string>
#include <string_view>
#include <vector>

namespace granota {

/// A text in the thesis's language and in English.
struct CaptionText {
    std::string ca;
    std::string en;
    const std::string& in(std::string_view language) const { return language == "ca" ? ca : en; }
};

/// One way to draw a figure: its name (`definition`, `thesis`, `n3`, `grabbed`, …), the
/// settings it adds over the figure's, the frog's input events ([step, kind, x, y] rows, as
/// a recording's), and what it shows in both languages.
struct FigureVariant {
    std::string name;
    Json state = Json::Object{};
    Json events = Json::Array{};
    CaptionText note;
};

struct ThesisFigure {
    std::string number;                  ///< "2.1" … "4.13"
    std::string tab;                     ///< decasteljau, bernstein, fit, catmull-rom, frog
    std::string example;                 ///< the worked example it loads first ("2.9"), or empty
    std::string scene;                   ///< the Frog tab's scene (run on the seed solver), or empty
    long steps = 0;                      ///< the scene's steps before the picture
    std::string art;                     ///< "head" or "background": the frog's art alone (Figs 4.11, 4.12)
    CaptionText caption;                 ///< the thesis's caption and its English
    Json state = Json::Object{};         ///< settings over the example's, for every variant
    std::vector<FigureVariant> variants; ///< at least one; the first is the default
};

/// The text of resources/figures/thesis_figures.json.
std::string_view thesisFiguresFile();

/// Every figure, in the thesis's order.
const std::vector<ThesisFigure>& thesisFigures();

/// The figure numbered `number` ("2.7"), or nullptr.
const ThesisFigure* findThesisFigure(std::string_view number);

/// The variant `name` of `figure` (empty: the default), or nullptr.
const FigureVariant* findFigureVariant(const ThesisFigure& figure, std::string_view name);

/// The variants' names, joined by ", " (for --list-figures and error messages).
std::string figureVariantNames(const ThesisFigure& figure);

} // namespace granota
