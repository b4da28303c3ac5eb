// The enum ⇄ name tables of core/base/enum_names.h, and what each of Granota's five name
// parsers accepts (the CLI's options and the saved documents depend on it).
#include "core/base/enum_names.h"
#include "core/curves/fitting/least_squares_fit.h"
#include "core/curves/fitting/parametrization.h"
#include "core/curves/splines/catmull_rom.h"
#include "core/softbody/integrators.h"
#include "core/softbody/simulation.h"

#include <QtTest>
#include "tests/test_main.h"

using namespace granota;

namespace {

enum class Colour { Red, Green, Blue };

constexpr std::array<EnumName<Colour>, 2> kColours{{{Colour::Red, "red"}, {Colour::Green, "green"}}};

static_assert(nameOf(kColours, Colour::Green) == "green", "nameOf is constexpr");

/// Every value's name reads back as that value.
template <class E, class Parse, class Name> bool roundTrips(std::initializer_list<E> values, Parse parse, Name name)
{
    for (E v : values)
        if (!(parse(name(v)) == std::optional<E>(v)))
            return false;
    return true;
}

const auto anyToString = [](auto v) { return toString(v); };

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
        QVERIFY(roundTrips({Integrator::ExplicitEuler, Integrator::SemiImplicitEuler, Integrator::Verlet, Integrator::Rk4},
                           parseIntegrator, integratorName));
        QCOMPARE(integratorName(Integrator::SemiImplicitEuler), std::string("semi-implicit-euler"));
        QVERIFY(parseIntegrator("RK4") == std::optional<Integrator>());
        QVERIFY(parseIntegrator(" rk4") == std::optional<Integrator>());
        QVERIFY(roundTrips({SolverKind::Seed, SolverKind::Stable}, parseSolverKind, solverName));
        QVERIFY(parseSolverKind("Seed") == std::optional<SolverKind>());
        QVERIFY(parseSolverKind("stable ") == std::optional<SolverKind>());
    }

    void fittingNamesIgnoreCaseButNotSpaces()
    {
        QVERIFY(roundTrips({LeastSquaresSolver::Qr, LeastSquaresSolver::Normal, LeastSquaresSolver::Svd}, parseLeastSquaresSolver,
                           anyToString));
        QVERIFY(parseLeastSquaresSolver("SVD") == std::optional<LeastSquaresSolver>(LeastSquaresSolver::Svd));
        QVERIFY(parseLeastSquaresSolver(" qr") == std::optional<LeastSquaresSolver>());
        QVERIFY(roundTrips({Parametrization::Uniform, Parametrization::ChordLength, Parametrization::Centripetal},
                           parseParametrization, anyToString));
        QVERIFY(parseParametrization("Chord") == std::optional<Parametrization>(Parametrization::ChordLength));
        QVERIFY(parseParametrization("chordal") == std::optional<Parametrization>());
        QVERIFY(parseParametrization("uniform ") == std::optional<Parametrization>());
    }

    void catmullRomModesIgnoreCaseAndSpaces()
    {
        QVERIFY(
            roundTrips({CatmullRomMode::Open, CatmullRomMode::Cyclic, CatmullRomMode::Closed}, parseCatmullRomMode, anyToString));
        QVERIFY(parseCatmullRomMode("  Closed\t") == std::optional<CatmullRomMode>(CatmullRomMode::Closed));
        QVERIFY(parseCatmullRomMode("loop") == std::optional<CatmullRomMode>());
    }
};

GRANOTA_TEST_APPLESS_MAIN(TestEnumNames)
#include "test_enum_names.moc"
