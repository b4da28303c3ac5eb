// The fuzz targets that need the widgets (documents, the Fitting tab's import) in the
// ordinary suite: every committed seed and every input that once made a target fail
// (tests/fuzz/regressions/<target>/) goes through the same property check as the fuzzer
// (tests/fuzz/ui_properties.h), on the same tabs built as the main window builds them.
#include "tests/fuzz/ui_properties.h"

#include "tests/fuzz/regression_inputs.h"

#include <QtTest>

namespace {

constexpr std::initializer_list<const char*> kTargets = {"document", "fit_import"};

} // namespace

class TestGuiFuzzRegressions : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { granota::fuzz::initUi(); }

    void everyTargetHasSeeds()
    {
        for (const char* target : kTargets)
            QVERIFY2(granota::fuzz::inputsOf(QLatin1String(target)).size() >= 3, target);
    }

    void replay_data() { granota::fuzz::addInputRows(kTargets); }
    void replay()
    {
        QFETCH(QString, target);
        QFETCH(QString, file);
        const auto bytes = granota::fuzz::readInput(file);
        QVERIFY2(bytes, qPrintable(file));
        const std::string finding = granota::fuzz::checkUi(target.toStdString(), granota::fuzz::view(*bytes));
        QVERIFY2(finding.empty(), finding.c_str());
    }
};

QTEST_MAIN(TestGuiFuzzRegressions)
#include "test_gui_fuzz_regressions.moc"
