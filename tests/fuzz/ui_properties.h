#pragma once
/// \file ui_properties.h
/// The properties of the two fuzz targets that need the widgets, shared by the libFuzzer
/// targets (fuzz_ui_main.cpp) and by tests/test_gui_fuzz_regressions.cpp. A QApplication
/// must exist (the offscreen platform is enough); the tabs are built as the main window
/// builds them and never shown.

#include <string>
#include <string_view>

namespace granota::fuzz {

/// Once, after the QApplication is made: test paths and settings, English texts.
void initUi();

/// ui/shell/document.h loadDocument, starting from the blank document (File ▸ New): a document
/// it refuses leaves every tab as it was and says why; one it accepts has only finite
/// numbers, and load → serializeDocument → load into fresh tabs → serializeDocument gives
/// the same bytes (the fresh tabs accept what was saved: the same validation as opening it).
std::string checkDocument(std::string_view input);

/// The Fitting tab's Import CSV… (FitTab::importFile, which reads with core/io/point_list's
/// parsePointFile): a refused file leaves the tab as it was and says why; an accepted one
/// gives the tab at least 2 points, all finite, exactly the doubles of what the file says,
/// and the tab's state then loads into another Fitting tab unchanged.
std::string checkFitImport(std::string_view input);

/// Calls the check named by `target` ("document", "fit_import").
std::string checkUi(std::string_view target, std::string_view input);

} // namespace granota::fuzz
