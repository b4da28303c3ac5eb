// The fuzz targets that need the widgets (documents, the Fitting tab's import) in the
// ordinary suite: every committed seed and every input that once made a target fail
// (tests/fuzz/regressions/<target>/) goes through the same property check as the fuzzer
// (tests/fuzz/ui_properties.h), on the same tabs built as the main window builds them.
#include "tests/fuzz/ui_properties.h"

#include "tests/fuzz/regression_inputs.h"

#include <QtTest>
#include "tests/test_main.h"

namespace {

constexpr std::initializer_list<const char*> kTargets = {"document", "fit_import"};

} // namespace

class TestGuiFuzzRegressions : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { granota::fuzz::initUi(); }

    void everyTargetHasSeeds() { granota::fuzz::verifyEveryTargetHasSeeds(kTargets); }

    void replay_data() { granota::fuzz::addInputRows(kTargets); }
    void replay() { granota::fuzz::replayInputRow(granota::fuzz::checkUi); }
};

GRANOTA_TEST_MAIN(TestGuiFuzzRegressions)
#include "test_gui_fuzz_regressions.moc"
