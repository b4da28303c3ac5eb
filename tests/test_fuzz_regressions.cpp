// The fuzz targets of the core (tests/fuzz) in the ordinary suite: every committed seed
// and every input that once made a target fail (tests/fuzz/regressions/<target>/) goes
// through the same property check as the fuzzer (tests/fuzz/properties.h), which
// answers with what it found wrong; a bug that comes back fails here by name.
#include "tests/fuzz/properties.h"

#include "tests/fuzz/regression_inputs.h"

#include <QtTest>
#include "tests/test_main.h"

namespace {

constexpr std::initializer_list<const char*> kTargets = {"json", "point_list", "rational", "polynomial", "scene"};

} // namespace

class TestFuzzRegressions : public QObject {
    Q_OBJECT
private slots:
    void everyTargetHasSeeds() { granota::fuzz::verifyEveryTargetHasSeeds(kTargets); }

    void replay_data() { granota::fuzz::addInputRows(kTargets); }
    void replay() { granota::fuzz::replayInputRow(granota::fuzz::checkCore); }
};

GRANOTA_TEST_GUILESS_MAIN(TestFuzzRegressions)
#include "test_fuzz_regressions.moc"
