#pragma once
/// \file fit_document.h
/// The Fitting tab's part of a .granota document besides its points (docs/file-formats.md):
/// the settings, what is drawn, the matrices and the curvature comb. Read all or nothing: a
/// bad value is refused with a translated message naming it, and nothing changes. A plain
/// value, read and written without a window.
/// Its texts keep the tab's translation context (granota::ui::FitTab), so the translations still match.

#include "ui/common/curve_tab.h"
#include "ui/fit/fit_display.h"
#include "ui/fit/fit_settings.h"

#include <QJsonObject>
#include <QString>

#include <optional>

namespace granota::ui {

struct FitDocument {
    FitSettings settings;
    FitDisplay display;
    bool showMatrices = false;  ///< the exact panel's matrices (Lemma 2.2, Note 2.2)
    bool curvatureComb = false; ///< the comb of the fitted curve (older documents: off)
    double combScale = 0;       ///< its scale, 0: automatic (older documents: automatic)

    /// The keys `degree`, `parametrization`, `solver`, `correctParameters`, `iterations`,
    /// `showMatrices`, `curvatureComb`, `curvatureCombScale` and fit_display.h's.
    void write(QJsonObject& state) const;
    /// Reads them (an absent key keeps the default); nullopt with the message in `error`.
    static std::optional<FitDocument> read(const QJsonObject& state, QString& error);
    /// What a document's data points are refused for.
    static PointListMessages pointMessages();
};

} // namespace granota::ui
