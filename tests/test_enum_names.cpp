// The enum ⇄ name tables of core/base/enum_names.h, and what each of Granota's five name
// parsers accepts (the CLI's options and the saved documents depend on it).
#include "core/base/enum_names.h"
#include "core/curves/fitting/least_squares_fit.h"
#include "core/curves/fitting/parametrization.h"
#include "core/curves/splines/catmull_rom.h"
#include "core/softbody/integrators.h"
#include "core/softbody/simulation.h"

#include <QtTest>

using namespace granota;

namespace {

enum class Colour { Red, Green, Blue };

constexpr std::array<EnumName<Colour>, 2> kColours{{{Colour::Red, "red"}, {Colour::Green, "green"}}};

static_assert(nameOf(kColours, Colour::Green) == "green", "nameOf is constexpr");

} // namespace

class TestEnumNames : public QObject {
    Q_OBJECT
private slots:
    void nameOfGivesTheTableNameOrTheFallback()
    {
        QCOMPARE(std::string(nameOf(kColours, Colour::Red)), std::string("red"));
        QCOMPARE(std::string(nameOf(kColours, Colour::Blue)), std::string());
        QCOMPARE(std::string(nameOf(kColours, Colour::Blue, "red")), std::string("red"));
    }

    void parseNameMatchesAsAsked()
    {
        QVERIFY(parseName(kColours, "green") == std::optional<Colour>(Colour::Green));
        QVERIFY(parseName(kColours, "Green") == std::optional<Colour>());
        QVERIFY(parseName(kColours, " green") == std::optional<Colour>());
        QVERIFY(parseName(kColours, "GrEeN", NameMatch::IgnoreCase) == std::optional<Colour>(Colour::Green));
        QVERIFY(parseName(kColours, " green", NameMatch::IgnoreCase) == std::optional<Colour>());
        QVERIFY(parseName(kColours, " \tRED \n", NameMatch::IgnoreCaseTrim) == std::optional<Colour>(Colour::Red));
        QVERIFY(parseName(kColours, "blue", NameMatch::IgnoreCaseTrim) == std::optional<Colour>());
        QVERIFY(parseName(kColours, "", NameMatch::IgnoreCaseTrim) == std::optional<Colour>());
    }

    void integratorsAndSolversAreExactLowerCase()
    {
        for (Integrator i : {Integrator::ExplicitEuler, Integrator::SemiImplicitEuler, Integrator::Verlet, Integrator::Rk4})
            QVERIFY(parseIntegrator(integratorName(i)) == std::optional<Integrator>(i));
        QCOMPARE(integratorName(Integrator::SemiImplicitEuler), std::string("semi-implicit-euler"));
        QVERIFY(parseIntegrator("RK4") == std::optional<Integrator>());
        QVERIFY(parseIntegrator(" rk4") == std::optional<Integrator>());
        for (SolverKind s : {SolverKind::Seed, SolverKind::Stable})
            QVERIFY(parseSolverKind(solverName(s)) == std::optional<SolverKind>(s));
        QVERIFY(parseSolverKind("Seed") == std::optional<SolverKind>());
        QVERIFY(parseSolverKind("stable ") == std::optional<SolverKind>());
    }

    void fittingNamesIgnoreCaseButNotSpaces()
    {
        for (LeastSquaresSolver s : {LeastSquaresSolver::Qr, LeastSquaresSolver::Normal, LeastSquaresSolver::Svd})
            QVERIFY(parseLeastSquaresSolver(toString(s)) == std::optional<LeastSquaresSolver>(s));
        QVERIFY(parseLeastSquaresSolver("SVD") == std::optional<LeastSquaresSolver>(LeastSquaresSolver::Svd));
        QVERIFY(parseLeastSquaresSolver(" qr") == std::optional<LeastSquaresSolver>());
        for (Parametrization p : {Parametrization::Uniform, Parametrization::ChordLength, Parametrization::Centripetal})
            QVERIFY(parseParametrization(toString(p)) == std::optional<Parametrization>(p));
        QVERIFY(parseParametrization("Chord") == std::optional<Parametrization>(Parametrization::ChordLength));
        QVERIFY(parseParametrization("chordal") == std::optional<Parametrization>());
        QVERIFY(parseParametrization("uniform ") == std::optional<Parametrization>());
    }

    void catmullRomModesIgnoreCaseAndSpaces()
    {
        for (CatmullRomMode m : {CatmullRomMode::Open, CatmullRomMode::Cyclic, CatmullRomMode::Closed})
            QVERIFY(parseCatmullRomMode(toString(m)) == std::optional<CatmullRomMode>(m));
        QVERIFY(parseCatmullRomMode("  Closed\t") == std::optional<CatmullRomMode>(CatmullRomMode::Closed));
        QVERIFY(parseCatmullRomMode("loop") == std::optional<CatmullRomMode>());
    }
};

QTEST_APPLESS_MAIN(TestEnumNames)
#include "test_enum_names.moc"
