// Least-squares Bézier fitting (§2.1.3): the exact matrices of Ex 2.7 and Ex 2.8, the
// chord-length parameters of Ex 2.9/2.10 (with the distances of the definition, not the
// thesis's slips), the optimality of Prop 2.2, and the numerical behaviour the thesis does
// not discuss: conditioning, rank deficiency, extreme data, parameter correction.
#include "core/curves/fitting/least_squares_fit.h"
#include "core/exact/moore_penrose.h"
#include "core/curves/fitting/parametrization.h"
#include "core/exact/polynomial.h"
#include "core/exact/rational.h"
#include "core/exact/rational_matrix.h"

#include <Eigen/Dense>

#include <algorithm>
#include <QElapsedTimer>
#include <QtTest>
#include "tests/test_main.h"

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

using namespace granota;

namespace {

Rational R(const QString& text)
{
    const std::optional<Rational> q = parseRational(text.toStdString());
    if (!q)
        qFatal("bad rational in the test: %s", qPrintable(text));
    return *q;
}

QString str(const RationalMatrix& m) { return QString::fromStdString(toText(m)); }

/// Q_0..Q_4 of Ex 2.7–2.10.
std::vector<RPoint> thesisPoints() { return {RPoint(0, 0), RPoint(1, 3), RPoint(4, 2), RPoint(8, -2), RPoint(1, 5)}; }

std::vector<Point> toPoints(const QVector<QPointF>& v)
{
    std::vector<Point> out;
    for (const QPointF& p : v)
        out.emplace_back(p.x(), p.y());
    return out;
}

/// Deterministic pseudo-random numbers in [−1, 1) (a 64-bit LCG).
class Lcg {
public:
    explicit Lcg(std::uint64_t seed) : m_s(seed) {}
    double next()
    {
        m_s = m_s * 6364136223846793005ULL + 1442695040888963407ULL;
        return static_cast<double>(m_s >> 11) / static_cast<double>(1ULL << 52) - 1.0;
    }

private:
    std::uint64_t m_s;
};

std::vector<Point> randomPoints(int count, std::uint64_t seed, double size = 5)
{
    Lcg rng(seed);
    std::vector<Point> q;
    for (int i = 0; i < count; ++i) {
        const double x = size * rng.next();
        q.emplace_back(x, size * rng.next());
    }
    return q;
}

/// A smooth closed-form curve sampled at s = i/(count−1), plus pseudo-noise.
std::vector<Point> smoothSamples(int count, double noise, std::uint64_t seed = 12345)
{
    Lcg rng(seed);
    std::vector<Point> q;
    for (int i = 0; i < count; ++i) {
        const double s = static_cast<double>(i) / (count - 1);
        const double x = std::cos(3 * s) + 0.5 * s + noise * rng.next();
        q.emplace_back(x, std::sin(2 * s) * std::exp(-s) + noise * rng.next());
    }
    return q;
}

Eigen::MatrixX2d toMatrix(const std::vector<Point>& p)
{
    Eigen::MatrixX2d m(static_cast<Eigen::Index>(p.size()), 2);
    for (std::size_t i = 0; i < p.size(); ++i)
        m.row(static_cast<Eigen::Index>(i)) << p[i].x, p[i].y;
    return m;
}

double maxAbs(const Eigen::MatrixXd& m) { return m.cwiseAbs().maxCoeff(); }

bool allFinite(const FitResult& f)
{
    bool ok = std::isfinite(f.sse) && std::isfinite(f.rms) && std::isfinite(f.maxError) && std::isfinite(f.cond);
    for (const Point& p : f.controlPoints)
        ok = ok && isFinite(p);
    for (const Point& p : f.residuals)
        ok = ok && isFinite(p);
    for (double t : f.params)
        ok = ok && std::isfinite(t);
    return ok;
}

bool hasWarning(const FitResult& f, const char* fragment)
{
    for (const std::string& w : f.warnings)
        if (w.find(fragment) != std::string::npos)
            return true;
    return false;
}

QString warnings(const FitResult& f)
{
    QStringList list;
    for (const std::string& w : f.warnings)
        list << QString::fromStdString(w);
    return list.join(" | ");
}

const LeastSquaresSolver kSolvers[] = {LeastSquaresSolver::Qr, LeastSquaresSolver::Normal, LeastSquaresSolver::Svd};
const Parametrization kParametrizations[] = {Parametrization::Uniform, Parametrization::ChordLength, Parametrization::Centripetal,
                                             Parametrization::AnnexIII};

FitOptions options(int degree, Parametrization p = Parametrization::Uniform, LeastSquaresSolver s = LeastSquaresSolver::Qr)
{
    FitOptions o;
    o.degree = degree;
    o.parametrization = p;
    o.solver = s;
    return o;
}

/// Prop 2.2: the residual r = Q − MP is orthogonal to every column of M (MᵀM P = MᵀQ).
/// Returns ‖Mᵀr‖ / (‖M‖‖r‖); when the curve (nearly) interpolates, r is rounding noise and
/// the measure is taken relative to a thousandth of the data, ‖M‖ · 1e−3‖Q‖, instead.
double normalEquationDefect(const std::vector<Point>& q, const FitResult& f)
{
    const int n = static_cast<int>(f.controlPoints.size()) - 1;
    const Eigen::MatrixXd M = bernsteinMatrix(f.params, n);
    const Eigen::MatrixX2d Q = toMatrix(q);
    const Eigen::MatrixX2d r = Q - M * toMatrix(f.controlPoints);
    const double scale = M.norm() * std::max(r.norm(), 1e-3 * Q.norm());
    return scale > 0 ? (M.transpose() * r).norm() / scale : 0.0;
}

} // namespace

Q_DECLARE_METATYPE(LeastSquaresSolver)
Q_DECLARE_METATYPE(Parametrization)

class TestLeastSquaresFit : public QObject {
    Q_OBJECT
private slots:
    void parseNames()
    {
        for (Parametrization p : kParametrizations)
            QCOMPARE(parseParametrization(toString(p)), std::optional<Parametrization>(p));
        for (LeastSquaresSolver s : kSolvers)
            QCOMPARE(parseLeastSquaresSolver(toString(s)), std::optional<LeastSquaresSolver>(s));
        QCOMPARE(parseParametrization("chord"), std::optional<Parametrization>(Parametrization::ChordLength));
        QCOMPARE(parseLeastSquaresSolver("QR"), std::optional<LeastSquaresSolver>(LeastSquaresSolver::Qr));
        QVERIFY(!parseParametrization("equidistant").has_value());
        QVERIFY(!parseParametrization("").has_value());
        QVERIFY(!parseLeastSquaresSolver("cholesky").has_value());
    }

    void rationalMatrix()
    {
        const RationalMatrix a{{R("2"), R("1")}, {R("1/2"), R("3")}};
        QCOMPARE(str(a.transpose()), QString("[2, 1/2; 1, 3]"));
        const auto inv = a.inverse();
        QVERIFY(inv.ok());
        QCOMPARE(a * *inv, RationalMatrix::identity(2));
        QCOMPARE(*inv * a, RationalMatrix::identity(2));
        // The first pivot is zero: the row exchange must find the nonzero one.
        const RationalMatrix b{{R("0"), R("1")}, {R("1"), R("0")}};
        QCOMPARE(*b.inverse(), b);
        const RationalMatrix rhs{{R("1")}, {R("7/3")}};
        const auto x = a.solve(rhs);
        QVERIFY(x.ok());
        QCOMPARE(a * *x, rhs);
        const RationalMatrix singular{{R("1"), R("2")}, {R("1/2"), R("1")}};
        QCOMPARE(singular.inverse().error().code, ErrorCode::Singular);
        QCOMPARE(RationalMatrix(2, 3).inverse().error().code, ErrorCode::InvalidInput);
        QCOMPARE(a.solve(RationalMatrix(3, 1)).error().code, ErrorCode::InvalidInput);
        const Eigen::MatrixXd d = a.toDouble();
        QCOMPARE(d(1, 0), 0.5);
        QCOMPARE(d.rows(), 2);
    }

    // ── Parameters (§2.1.3, the criteria after Nota 2.2) ───────────────────────────────

    void exactParametersWhenDistancesAreRational()
    {
        // Chord length: d = 5, 13, 4, so t = 0, 5/22, 18/22, 1.
        const std::vector<RPoint> chord{RPoint(0, 0), RPoint(3, 4), RPoint(8, 16), RPoint(8, 20)};
        const auto t = exactParameters(chord, Parametrization::ChordLength);
        QVERIFY(t.has_value());
        QCOMPARE(*t, (std::vector<Rational>{R("0"), R("5/22"), R("9/11"), R("1")}));
        const std::vector<double> td = parameters(toDouble(chord), Parametrization::ChordLength);
        for (std::size_t i = 0; i < td.size(); ++i)
            QVERIFY(std::fabs(td[i] - (*t)[i].get_d()) <= 1e-15);
        // Centripetal: √5 is irrational there …
        QVERIFY(!exactParameters(chord, Parametrization::Centripetal).has_value());
        // … but d = 4, 9, 4 gives √d = 2, 3, 2 and t = 0, 2/7, 5/7, 1.
        const std::vector<RPoint> square{RPoint(0, 0), RPoint(4, 0), RPoint(4, 9), RPoint(0, 9)};
        const auto tc = exactParameters(square, Parametrization::Centripetal);
        QVERIFY(tc.has_value());
        QCOMPARE(*tc, (std::vector<Rational>{R("0"), R("2/7"), R("5/7"), R("1")}));
        const std::vector<double> tcd = parameters(toDouble(square), Parametrization::Centripetal);
        for (std::size_t i = 0; i < tcd.size(); ++i)
            QVERIFY(std::fabs(tcd[i] - (*tc)[i].get_d()) <= 1e-15);
        // Uniform: t_i = i/k always.
        QCOMPARE(*exactParameters(thesisPoints(), Parametrization::Uniform),
                 (std::vector<Rational>{R("0"), R("1/4"), R("1/2"), R("3/4"), R("1")}));
    }

    // Annex III's BezParamProp as the thesis computes it (issue 33, part 3): d_j = |Q_{j−1}|.
    // Ex 2.9's points: |Q_0|, |Q_1|, |Q_2|, |Q_3| = 0, √10, √20, √68, so t = 0, 0,
    // √10/Σ = 0.19913, (√10 + √20)/Σ = 0.48074, 1 (by hand; the figures). With them
    // the n = 3 fit is worse than uniform: Σ‖Q_i − α(t_i)‖² = 5.000 against 4.143, where the
    // definition's chord length gives 0.237 (the figures, computed apart).
    void annexIIIParametersAreTheThesissOwn()
    {
        const std::vector<Point> q{{0, 0}, {1, 3}, {4, 2}, {8, -2}, {1, 5}};
        const std::vector<double> t = parameters(q, Parametrization::AnnexIII);
        const double sum = std::sqrt(10.0) + std::sqrt(20.0) + std::sqrt(68.0);
        const double expected[] = {0, 0, std::sqrt(10.0) / sum, (std::sqrt(10.0) + std::sqrt(20.0)) / sum, 1};
        for (int i = 0; i < 5; ++i)
            QVERIFY2(std::fabs(t[std::size_t(i)] - expected[i]) < 1e-15, qPrintable(QString::number(t[std::size_t(i)])));
        QVERIFY(std::fabs(t[2] - 0.19913) < 5e-6 && std::fabs(t[3] - 0.48074) < 5e-6);
        const auto sse = [&q](Parametrization p) {
            const auto f = fitBezier(q, options(3, p));
            return f ? f->sse : -1.0;
        };
        QVERIFY2(std::fabs(sse(Parametrization::AnnexIII) - 5.000) < 5e-4,
                 qPrintable(QString::number(sse(Parametrization::AnnexIII))));
        QVERIFY(std::fabs(sse(Parametrization::Uniform) - 4.143) < 5e-4);
        QVERIFY(std::fabs(sse(Parametrization::ChordLength) - 0.237) < 5e-4);
        // Exactly, when every |Q_j| is rational: 5, 5, 10 give t = 0, 1/4, 1/2, 1.
        const std::vector<RPoint> pythagorean{RPoint(3, 4), RPoint(0, 5), RPoint(6, 8), RPoint(1, 1)};
        const auto exact = exactParameters(pythagorean, Parametrization::AnnexIII);
        QVERIFY(exact.has_value());
        QCOMPARE(*exact, (std::vector<Rational>{R("0"), R("1/4"), R("1/2"), R("1")}));
        QVERIFY(!exactParameters(toRational(q), Parametrization::AnnexIII).has_value()); // √10
    }

    void parametersSurviveExtremeCoordinates()
    {
        // Differences of ±1.5e308 overflow a double; the parameters must not.
        const std::vector<Point> huge{Point(-1.5e308, 0), Point(1.5e308, 0), Point(1.5e308, 1e308)};
        const std::vector<double> t = parameters(huge, Parametrization::ChordLength);
        QCOMPARE(t.front(), 0.0);
        QCOMPARE(t.back(), 1.0);
        QVERIFY(std::fabs(t[1] - 0.75) <= 1e-15);
        // Scaling by a power of two changes nothing, even far beyond 1e300 or below 1e−300 …
        const std::vector<Point> q = randomPoints(20, 7);
        for (int e : {-1000, 1000}) {
            std::vector<Point> scaled;
            for (const Point& p : q)
                scaled.emplace_back(std::ldexp(p.x, e), std::ldexp(p.y, e));
            for (Parametrization p : {Parametrization::ChordLength, Parametrization::Centripetal})
                QCOMPARE(parameters(scaled, p), parameters(q, p));
        }
        // … and subnormal coordinates (a few bits each) still give proper parameters.
        std::vector<Point> tiny;
        for (const Point& p : q)
            tiny.emplace_back(std::ldexp(p.x, -1060), std::ldexp(p.y, -1060));
        for (Parametrization p : {Parametrization::ChordLength, Parametrization::Centripetal}) {
            bool fellBack = true;
            const std::vector<double> t = parameters(tiny, p, &fellBack);
            QVERIFY(!fellBack);
            const std::vector<double> reference = parameters(q, p);
            for (std::size_t i = 0; i < t.size(); ++i)
                QVERIFY(std::fabs(t[i] - reference[i]) <= 1e-3);
        }
        for (Parametrization p : kParametrizations) {
            const std::vector<double> tp = parameters(q, p);
            QCOMPARE(tp.front(), 0.0);
            QCOMPARE(tp.back(), 1.0);
            for (std::size_t i = 1; i < tp.size(); ++i)
                QVERIFY(tp[i] > tp[i - 1]);
        }
    }

    // ── Ex 2.7 and Ex 2.8: every matrix as printed in the thesis ─────────────────────────

    void thesisExamplesExactly_data()
    {
        QTest::addColumn<int>("degree");
        QTest::addColumn<QString>("M");
        QTest::addColumn<QString>("Mt");
        QTest::addColumn<QString>("MtM");
        QTest::addColumn<QString>("MtMinv");
        QTest::addColumn<QString>("Mplus");
        QTest::addColumn<QString>("P");
        QTest::addColumn<QStringList>("alphaX"); // α(t) in powers of t, as printed
        QTest::addColumn<QStringList>("alphaY");
        QTest::newRow("Ex 2.7") << 2 << "[1, 0, 0; 9/16, 3/8, 1/16; 1/4, 1/2, 1/4; 1/16, 3/8, 9/16; 0, 0, 1]"
                                << "[1, 9/16, 1/4, 1/16, 0; 0, 3/8, 1/2, 3/8, 0; 0, 1/16, 1/4, 9/16, 1]"
                                << "[177/128, 23/64, 17/128; 23/64, 17/32, 23/64; 17/128, 23/64, 177/128]"
                                << "[31/35, -23/35, 3/35; -23/35, 97/35, -23/35; 3/35, -23/35, 31/35]"
                                << "[31/35, 9/35, -3/35, -1/7, 3/35; -23/35, 22/35, 37/35, 22/35, -23/35; "
                                   "3/35, -1/7, -3/35, 9/35, 31/35]"
                                << "[-8/7, 46/35; 323/35, -19/35; 86/35, 116/35]" << QStringList{"-8/7", "726/35", "-600/35"}
                                << QStringList{"46/35", "-130/35", "200/35"};
        QTest::newRow("Ex 2.8")
            << 3 << "[1, 0, 0, 0; 27/64, 27/64, 9/64, 1/64; 1/8, 3/8, 3/8, 1/8; 1/64, 9/64, 27/64, 27/64; 0, 0, 0, 1]"
            << "[1, 27/64, 1/8, 1/64, 0; 0, 27/64, 3/8, 9/64, 0; 0, 9/64, 3/8, 27/64, 0; 0, 1/64, 1/8, 27/64, 1]"
            << "[2445/2048, 465/2048, 231/2048, 59/2048; 465/2048, 693/2048, 531/2048, 231/2048; "
               "231/2048, 531/2048, 693/2048, 465/2048; 59/2048, 231/2048, 465/2048, 2445/2048]"
            << "[69/70, -629/630, 281/630, -1/70; -629/630, 47389/5670, -36121/5670, 281/630; "
               "281/630, -36121/5670, 47389/5670, -629/630; -1/70, 281/630, -629/630, 69/70]"
            << "[69/70, 2/35, -3/35, 2/35, -1/70; -629/630, 698/315, 71/105, -422/315, 281/630; "
               "281/630, -422/315, 71/105, 698/315, -629/630; -1/70, 2/35, -3/35, 2/35, 69/70]"
            << "[11/70, -13/70; -3371/630, 2711/210; 11399/630, -2539/210; 81/70, 337/70]"
            // The thesis prints -1636/105 for the t coefficient of x(t): a slip, since
            // α′(0) = 3(P_1 − P_0) = 3(-3371/630 - 11/70) = -347/21 = -1735/105. The other
            // seven coefficients are as printed.
            << QStringList{"11/70", "-347/21", "608/7", "-208/3"} << QStringList{"-13/70", "275/7", "-800/7", "80"};
    }
    // §2.1.3 checked (issue 33, part 4): the thesis's M⁺ of Ex 2.7 (typed from the print)
    // meets the four Penrose conditions in its order; one entry changed breaks them. The
    // Hessian 2MᵀM is the thesis's MᵀM doubled, and its eigenvalues are 2σ_i², σ_i from
    // Eigen's SVD of M (another algorithm), all positive: Prop 2.2's minimum.
    void penroseConditionsAndTheHessian()
    {
        const RationalMatrix M{{R("1"), R("0"), R("0")},
                               {R("9/16"), R("3/8"), R("1/16")},
                               {R("1/4"), R("1/2"), R("1/4")},
                               {R("1/16"), R("3/8"), R("9/16")},
                               {R("0"), R("0"), R("1")}};
        RationalMatrix Mplus{{R("31/35"), R("9/35"), R("-3/35"), R("-1/7"), R("3/35")},
                             {R("-23/35"), R("22/35"), R("37/35"), R("22/35"), R("-23/35")},
                             {R("3/35"), R("-1/7"), R("-3/35"), R("9/35"), R("31/35")}};
        QCOMPARE(penroseConditions(M, Mplus), (std::array<bool, 4>{true, true, true, true}));
        RationalMatrix wrong = Mplus;
        wrong(1, 2) = R("36/35");
        const auto broken = penroseConditions(M, wrong);
        QVERIFY(!broken[0] || !broken[1] || !broken[2] || !broken[3]);
        QVERIFY(!broken[0]);
        QCOMPARE(penroseConditions(M, M), (std::array<bool, 4>{false, false, false, false})); // not even its shape
        const RationalMatrix H = leastSquaresHessian(M);
        QCOMPARE(str(H), QStringLiteral("[177/64, 23/32, 17/64; 23/32, 17/16, 23/32; 17/64, 23/32, 177/64]"));
        Eigen::MatrixXd md(5, 3);
        for (int r = 0; r < 5; ++r)
            for (int c = 0; c < 3; ++c)
                md(r, c) = toDouble(M(r, c));
        const Eigen::JacobiSVD<Eigen::MatrixXd> svd(md);
        std::vector<double> expected;
        for (Eigen::Index i = 0; i < svd.singularValues().size(); ++i)
            expected.push_back(2 * svd.singularValues()(i) * svd.singularValues()(i));
        std::sort(expected.begin(), expected.end());
        const std::vector<double> eigenvalues = symmetricEigenvalues(H);
        QCOMPARE(eigenvalues.size(), expected.size());
        for (std::size_t i = 0; i < expected.size(); ++i)
            QVERIFY(std::fabs(eigenvalues[i] - expected[i]) <= 1e-13 * expected.back());
        QVERIFY(eigenvalues.front() > 0);
    }
    void thesisExamplesExactly()
    {
        QFETCH(int, degree);
        QFETCH(QString, M);
        QFETCH(QString, Mt);
        QFETCH(QString, MtM);
        QFETCH(QString, MtMinv);
        QFETCH(QString, Mplus);
        QFETCH(QString, P);
        QFETCH(QStringList, alphaX);
        QFETCH(QStringList, alphaY);

        const auto fit = fitBezierExact(thesisPoints(), degree, Parametrization::Uniform);
        QVERIFY(fit.ok());
        QCOMPARE(fit->params, (std::vector<Rational>{R("0"), R("1/4"), R("1/2"), R("3/4"), R("1")}));
        QCOMPARE(str(fit->M), M);
        QCOMPARE(str(fit->M.transpose()), Mt);
        QCOMPARE(str(fit->MtM), MtM);
        QCOMPARE(str(fit->MtMinv), MtMinv);
        QCOMPARE(str(fit->Mplus), Mplus);
        QCOMPARE(str(fit->P), P);

        // The identities behind them: (MᵀM)(MᵀM)⁻¹ = I, M⁺M = I (Nota 2.2: M has full
        // rank) and the normal equations MᵀM P = MᵀQ (Prop 2.2).
        const int m = degree + 1;
        QCOMPARE(fit->MtM * fit->MtMinv, RationalMatrix::identity(m));
        QCOMPARE(fit->Mplus * fit->M, RationalMatrix::identity(m));
        RationalMatrix Q(5, 2);
        for (int i = 0; i < 5; ++i) {
            Q(i, 0) = thesisPoints()[static_cast<std::size_t>(i)].x;
            Q(i, 1) = thesisPoints()[static_cast<std::size_t>(i)].y;
        }
        QCOMPARE(fit->MtM * fit->P, fit->M.transpose() * Q);
        // The error of Prop 2.2, recomputed from the residual.
        const RationalMatrix r = fit->M * fit->P;
        Rational sse(0);
        for (int i = 0; i < 5; ++i)
            for (int c = 0; c < 2; ++c)
                sse += Rational((Q(i, c) - r(i, c)) * (Q(i, c) - r(i, c)));
        QCOMPARE(fit->sse, sse);

        // α(t) = Σ B_j^n(t) P_j in powers of t, against the printed polynomials.
        using Poly = Polynomial<Rational>;
        const Poly t = Poly::identity();
        const Poly u = Poly(1) - t;
        Poly x, y;
        for (int j = 0; j <= degree; ++j) {
            Poly b(binomial(degree, j));
            for (int a = 0; a < j; ++a)
                b *= t;
            for (int a = 0; a < degree - j; ++a)
                b *= u;
            x += b * Poly(fit->P(j, 0));
            y += b * Poly(fit->P(j, 1));
        }
        if (degree == 3)
            QVERIFY(x.coefficient(1) != R("-1636/105")); // the printed slip, see the data row
        for (int k = 0; k <= degree; ++k) {
            QCOMPARE(x.coefficient(k), R(alphaX[k]));
            QCOMPARE(y.coefficient(k), R(alphaY[k]));
        }
        // The t coefficient is α′(0) = n(P_1 − P_0), whatever the printed text says.
        QCOMPARE(x.coefficient(1), Rational(degree * (fit->P(1, 0) - fit->P(0, 0))));
        QCOMPARE(y.coefficient(1), Rational(degree * (fit->P(1, 1) - fit->P(0, 1))));
    }

    void floatingPointSolversMatchExact_data()
    {
        QTest::addColumn<int>("degree");
        QTest::addColumn<LeastSquaresSolver>("solver");
        for (int degree : {2, 3})
            for (LeastSquaresSolver s : kSolvers)
                QTest::addRow("Ex 2.%d %s", degree + 5, toString(s).c_str()) << degree << s;
    }
    void floatingPointSolversMatchExact()
    {
        QFETCH(int, degree);
        QFETCH(LeastSquaresSolver, solver);
        const auto exact = fitBezierExact(thesisPoints(), degree, Parametrization::Uniform);
        QVERIFY(exact.ok());
        const std::vector<Point> q = toDouble(thesisPoints());
        const auto fit = fitBezier(q, options(degree, Parametrization::Uniform, solver));
        QVERIFY2(fit.ok(), fit ? "" : fit.error().message.c_str());
        const Eigen::MatrixXd P = exact->P.toDouble();
        QCOMPARE(fit->controlPoints.size(), static_cast<std::size_t>(degree + 1));
        QVERIFY(maxAbs(toMatrix(fit->controlPoints) - P) <= 1e-12);
        QVERIFY(std::fabs(fit->sse - exact->sse.get_d()) <= 1e-12 * exact->sse.get_d());
        const Eigen::MatrixX2d residual = toMatrix(q) - exact->M.toDouble() * P;
        QVERIFY(maxAbs(toMatrix(fit->residuals) - residual) <= 1e-12);
        QCOMPARE(fit->rms, std::sqrt(fit->sse / 5));
        QCOMPARE(fit->maxError, residual.rowwise().norm().maxCoeff());
        // cond₂(M), independently from the singular values of the exact M.
        const Eigen::VectorXd sigma = Eigen::JacobiSVD<Eigen::MatrixXd>(exact->M.toDouble()).singularValues();
        QVERIFY(std::fabs(fit->cond - sigma(0) / sigma(degree)) <= 1e-12 * fit->cond);
        QVERIFY(fit->warnings.empty());
        QCOMPARE(fit->corrections, 0);
    }

    // ── Ex 2.9 and Ex 2.10: chord length with d_i = |Q_i − Q_{i−1}| ──────────────────────

    void thesisChordLengthParameters()
    {
        const std::vector<Point> q = toDouble(thesisPoints());
        // d = √10, √10, 4√2, 7√2: Q_3 = (8, −2), so d_4 = |(1 − 8, 5 + 2)| = 7√2.
        const double s10 = std::sqrt(10.0), s2 = std::sqrt(2.0);
        const double total = 2 * s10 + 11 * s2;
        const std::vector<double> expected{0, s10 / total, 2 * s10 / total, (2 * s10 + 4 * s2) / total, 1};
        const std::vector<double> t = parameters(q, Parametrization::ChordLength);
        QCOMPARE(t.size(), expected.size());
        for (std::size_t i = 0; i < t.size(); ++i)
            QVERIFY2(std::fabs(t[i] - expected[i]) <= 1e-15, qPrintable(QString("t_%1 = %2").arg(i).arg(t[i])));

        // The thesis prints t_1..t_3 from d_4 = √85 (it wrote 1 − 7): its closed forms are
        // those of the slip, and they are not the parameters of the definition.
        const double s5 = std::sqrt(5.0), s34 = std::sqrt(34.0), s170 = std::sqrt(170.0);
        const double slipTotal = 2 * s10 + 4 * s2 + std::sqrt(85.0);
        const double printed[] = {(1540 + 744 * s5 - 65 * s34 - 160 * s170) / 4951,
                                  (3080 + 1488 * s5 - 130 * s34 - 320 * s170) / 4951,
                                  (6056 + 2720 * s5 - 770 * s34 - 372 * s170) / 4951};
        const double slip[] = {s10 / slipTotal, 2 * s10 / slipTotal, (2 * s10 + 4 * s2) / slipTotal};
        for (int i = 0; i < 3; ++i) {
            QVERIFY(std::fabs(printed[i] - slip[i]) <= 1e-12);
            QVERIFY(std::fabs(t[static_cast<std::size_t>(i + 1)] - printed[i]) > 1e-3);
        }

        // The distances are irrational: no exact fit, and the message says why.
        QVERIFY(!exactParameters(thesisPoints(), Parametrization::ChordLength).has_value());
        QVERIFY(!exactParameters(thesisPoints(), Parametrization::Centripetal).has_value());
        const auto exact = fitBezierExact(thesisPoints(), 2, Parametrization::ChordLength);
        QVERIFY(!exact.ok());
        QCOMPARE(exact.error().code, ErrorCode::NotRational);
        QVERIFY(QString::fromStdString(exact.error().message).contains("irrational"));
        QVERIFY(QString::fromStdString(exact.error().message).contains("√(10)"));
    }

    void thesisChordLengthFits_data()
    {
        QTest::addColumn<int>("degree");
        QTest::addColumn<LeastSquaresSolver>("solver");
        for (int degree : {2, 3})
            for (LeastSquaresSolver s : kSolvers)
                QTest::addRow("Ex 2.%d %s", degree + 7, toString(s).c_str()) << degree << s;
    }
    void thesisChordLengthFits()
    {
        QFETCH(int, degree);
        QFETCH(LeastSquaresSolver, solver);
        const std::vector<Point> q = toDouble(thesisPoints());
        const auto chord = fitBezier(q, options(degree, Parametrization::ChordLength, solver));
        QVERIFY(chord.ok());
        QCOMPARE(chord->params, parameters(q, Parametrization::ChordLength));
        QVERIFY(normalEquationDefect(q, *chord) <= 1e-13);
        // The thesis's closing remark: proportional t_i fit better than equidistant ones.
        const auto uniform = fitBezier(q, options(degree, Parametrization::Uniform, solver));
        QVERIFY(uniform.ok());
        QVERIFY(chord->sse < uniform->sse);
        qInfo("degree %d: SSE %.6g (chord length) < %.6g (uniform)", degree, chord->sse, uniform->sse);
    }

    // ── Prop 2.2: the fit minimises Σ‖Q_i − α(t_i)‖² ─────────────────────────────────────

    void leastSquaresOptimality_data()
    {
        QTest::addColumn<Parametrization>("parametrization");
        QTest::addColumn<LeastSquaresSolver>("solver");
        for (Parametrization p : kParametrizations)
            for (LeastSquaresSolver s : kSolvers)
                QTest::addRow("%s %s", toString(p).c_str(), toString(s).c_str()) << p << s;
    }
    void leastSquaresOptimality()
    {
        QFETCH(Parametrization, parametrization);
        QFETCH(LeastSquaresSolver, solver);
        for (std::uint64_t seed = 1; seed <= 4; ++seed) {
            const std::vector<Point> q = randomPoints(25, seed);
            for (int degree = 0; degree <= 8; ++degree) {
                const auto fit = fitBezier(q, options(degree, parametrization, solver));
                QVERIFY(fit.ok());
                QVERIFY(allFinite(*fit));
                QCOMPARE(fit->params, parameters(q, parametrization));
                const Eigen::MatrixXd M = bernsteinMatrix(fit->params, degree);
                const Eigen::MatrixX2d P = toMatrix(fit->controlPoints);
                const Eigen::MatrixX2d Q = toMatrix(q);
                // The reported residuals and error are those of the returned curve.
                QVERIFY(maxAbs(toMatrix(fit->residuals) - (Q - M * P)) <= 1e-12);
                QVERIFY(std::fabs(fit->sse - (Q - M * P).squaredNorm()) <= 1e-12 * fit->sse);
                // Mᵀr = 0 …
                const double defect = normalEquationDefect(q, *fit);
                QVERIFY2(defect <= 1e-11, qPrintable(QString("degree %1: |Mᵀr|/(|M||r|) = %2").arg(degree).arg(defect)));
                // … so moving any control point anywhere makes the error larger.
                for (int j = 0; j <= degree; ++j)
                    for (const Point& d : {Point(1, 0), Point(-1, 0), Point(0, 1), Point(0, -1), Point(0.6, -0.8)}) {
                        Eigen::MatrixX2d moved = P;
                        moved(j, 0) += 1e-3 * d.x;
                        moved(j, 1) += 1e-3 * d.y;
                        QVERIFY((Q - M * moved).squaredNorm() > fit->sse);
                    }
            }
        }
    }

    // ── Numerical stability: what the thesis's normal equations cannot do ───────────────

    void degree30AgainstExactReference()
    {
        const int degree = 30;
        const std::vector<Point> q = smoothSamples(200, 1e-3);
        QElapsedTimer clock;
        clock.start();
        // t_i = i/199. A reference computed on purpose: beyond the budget a user's --exact
        // gets (kMaxExactWork), so the budget is given.
        const std::vector<RPoint> rq = toRational(q);
        std::vector<Rational> t;
        for (int i = 0; i < 200; ++i)
            t.push_back(frac(i, 199));
        const double work = fitExactWork(degree, t, maxBitLength(rq));
        QVERIFY(work > kMaxExactWork); // else the budget below is not needed
        const auto exact = fitBezierExact(rq, degree, Parametrization::Uniform, 2 * work);
        const qint64 exactMs = clock.elapsed();
        QVERIFY(exact.ok());
        const Eigen::MatrixXd reference = exact->P.toDouble();
        const double size = maxAbs(reference);
        const auto relativeError = [&](const FitResult& f) { return maxAbs(toMatrix(f.controlPoints) - reference) / size; };

        const auto qr = fitBezier(q, options(degree)); // the default solver
        QVERIFY(qr.ok());
        QVERIFY(allFinite(*qr));
        const double qrError = relativeError(*qr);
        const auto svd = fitBezier(q, options(degree, Parametrization::Uniform, LeastSquaresSolver::Svd));
        QVERIFY(svd.ok());
        const double svdError = relativeError(*svd);
        const auto normal = fitBezier(q, options(degree, Parametrization::Uniform, LeastSquaresSolver::Normal));
        const double normalError = normal ? relativeError(*normal) : std::numeric_limits<double>::quiet_NaN();

        qInfo("degree 30, 200 points: cond2(M) = %.3g, max |P| = %.3g; relative error of the control points: "
              "qr %.3g, svd %.3g, normal %s; exact reference in %lld ms",
              qr->cond, size, qrError, svdError,
              normal ? qPrintable(QString::number(normalError, 'g', 3))
                     : qPrintable("error: " + QString::fromStdString(normal.error().message)),
              static_cast<long long>(exactMs));
        QVERIFY(qrError < 1e-6);
        QVERIFY(svdError < 1e-6);
        if (normal)
            QVERIFY(normalError > 1e-3); // the normal equations square cond₂(M)
        else
            QCOMPARE(normal.error().code, ErrorCode::Singular);
        // The residuals agree even so: the error lives in directions M barely sees.
        QVERIFY(std::fabs(qr->sse - exact->sse.get_d()) <= 1e-6 * exact->sse.get_d());
        // cond₂(M) from the R factor, against the singular values of M itself.
        const Eigen::VectorXd sigma = Eigen::JacobiSVD<Eigen::MatrixXd>(exact->M.toDouble()).singularValues();
        QVERIFY(std::fabs(qr->cond - sigma(0) / sigma(degree)) <= 1e-4 * qr->cond);
    }

    void conditionNumberGrowsWithDegree()
    {
        const std::vector<Point> q = smoothSamples(100, 0);
        double previous = 0;
        for (int degree = 0; degree <= 25; ++degree) {
            const auto fit = fitBezier(q, options(degree));
            QVERIFY(fit.ok());
            const Eigen::VectorXd sigma =
                Eigen::JacobiSVD<Eigen::MatrixXd>(bernsteinMatrix(fit->params, degree)).singularValues();
            QVERIFY(std::fabs(fit->cond - sigma(0) / sigma(degree)) <= 1e-6 * fit->cond);
            if (degree == 0)
                QVERIFY(std::fabs(fit->cond - 1) <= 1e-14); // M is a column of ones
            else
                QVERIFY2(fit->cond > previous, qPrintable(QString("degree %1: %2").arg(degree).arg(fit->cond)));
            QCOMPARE(hasWarning(*fit, "ill-conditioned"), fit->cond > 1e10);
            previous = fit->cond;
        }
        qInfo("cond2(M) at degree 25 with 100 uniform parameters: %.3g", previous);
    }

    // ── Bad and degenerate input ──────────────────────────────────────────────────────

    void rejectsBadInput_data()
    {
        QTest::addColumn<QVector<QPointF>>("points");
        QTest::addColumn<int>("degree");
        QTest::addColumn<int>("code");
        QTest::addColumn<QString>("fragment");
        const double nan = std::numeric_limits<double>::quiet_NaN();
        const double inf = std::numeric_limits<double>::infinity();
        const QVector<QPointF> five{{0, 0}, {1, 3}, {4, 2}, {8, -2}, {1, 5}};
        QVector<QPointF> many;
        for (int i = 0; i < 200; ++i)
            many << QPointF(i, std::sin(i));
        QTest::newRow("NaN") << QVector<QPointF>{{0, 0}, {1, 1}, {nan, 2}, {3, 3}} << 2 << int(ErrorCode::InvalidInput) << "Q_2";
        QTest::newRow("+inf") << QVector<QPointF>{{0, inf}, {1, 1}, {2, 2}} << 1 << int(ErrorCode::InvalidInput) << "Q_0";
        QTest::newRow("-inf") << QVector<QPointF>{{0, 0}, {1, 1}, {2, 2}, {-inf, 3}} << 1 << int(ErrorCode::InvalidInput)
                              << "Q_3";
        QTest::newRow("no points") << QVector<QPointF>{} << 0 << int(ErrorCode::TooFewPoints) << "at least 2";
        QTest::newRow("one point") << QVector<QPointF>{{1, 2}} << 0 << int(ErrorCode::TooFewPoints) << "at least 2";
        QTest::newRow("degree = number of points") << five << 5 << int(ErrorCode::DegreeTooHigh) << "needs at least 6";
        QTest::newRow("degree far too high") << five.mid(0, 3) << 10 << int(ErrorCode::DegreeTooHigh) << "at most 2";
        QTest::newRow("negative degree") << five << -1 << int(ErrorCode::OutOfRange) << "-1";
        QTest::newRow("degree 101") << many << 101 << int(ErrorCode::OutOfRange) << "100";
    }
    void rejectsBadInput()
    {
        QFETCH(QVector<QPointF>, points);
        QFETCH(int, degree);
        QFETCH(int, code);
        QFETCH(QString, fragment);
        const std::vector<Point> q = toPoints(points);
        for (Parametrization p : kParametrizations)
            for (LeastSquaresSolver s : kSolvers) {
                const auto fit = fitBezier(q, options(degree, p, s));
                QVERIFY(!fit.ok());
                QCOMPARE(int(fit.error().code), code);
                QVERIFY2(QString::fromStdString(fit.error().message).contains(fragment), fit.error().message.c_str());
            }
        bool finite = true;
        for (const Point& p : q)
            finite = finite && isFinite(p);
        if (finite) {
            const auto exact = fitBezierExact(toRational(q), degree, Parametrization::Uniform);
            QVERIFY(!exact.ok());
            QCOMPARE(int(exact.error().code), code);
        }
    }

    void coincidentPoints_data()
    {
        QTest::addColumn<Parametrization>("parametrization");
        QTest::addColumn<LeastSquaresSolver>("solver");
        for (Parametrization p : {Parametrization::ChordLength, Parametrization::Centripetal})
            for (LeastSquaresSolver s : kSolvers)
                QTest::addRow("%s %s", toString(p).c_str(), toString(s).c_str()) << p << s;
    }
    void coincidentPoints()
    {
        QFETCH(Parametrization, parametrization);
        QFETCH(LeastSquaresSolver, solver);
        // Zero chord lengths: t = 0, 0, a, a, b, c, 1 — only 5 distinct parameters.
        const std::vector<Point> q{Point(0, 0), Point(0, 0), Point(1, 1), Point(1, 1), Point(2, 0), Point(3, 2), Point(4, -1)};
        const std::vector<double> t = parameters(q, parametrization);
        QCOMPARE(t[0], t[1]);
        QCOMPARE(t[2], t[3]);

        // Degree 3: n + 1 = 4 ≤ 5 distinct parameters, M has full rank (Lemma 2.2).
        const auto cubic = fitBezier(q, options(3, parametrization, solver));
        QVERIFY(cubic.ok());
        QVERIFY(allFinite(*cubic));
        QVERIFY(!hasWarning(*cubic, "rank deficient"));
        QVERIFY(cubic->sse > 1e-3);
        QVERIFY(normalEquationDefect(q, *cubic) <= 1e-12);

        // Degree 5: 6 control points but 5 distinct parameters, M is rank deficient.
        const auto quintic = fitBezier(q, options(5, parametrization, solver));
        if (solver == LeastSquaresSolver::Normal) {
            QVERIFY(!quintic.ok());
            QCOMPARE(quintic.error().code, ErrorCode::Singular);
            QVERIFY(QString::fromStdString(quintic.error().message).contains("distinct"));
        } else {
            QVERIFY2(quintic.ok(), quintic ? "" : quintic.error().message.c_str());
            QVERIFY(allFinite(*quintic));
            QVERIFY2(hasWarning(*quintic, "rank deficient"), qPrintable(warnings(*quintic)));
            // Still a least-squares solution (it interpolates the 5 distinct points).
            QVERIFY(normalEquationDefect(q, *quintic) <= 1e-12);
            QVERIFY(quintic->sse <= 1e-20);
            // Of the many least-squares solutions, the minimum-norm one stays of the size of
            // the data (others are arbitrarily large).
            for (const Point& p : quintic->controlPoints)
                QVERIFY(norm(p) < 100);
        }
    }

    void coincidentPointsExactly()
    {
        // Rational distances 0, 5, 0, 4, 3: t = 0, 0, 5/12, 5/12, 3/4, 1.
        const std::vector<RPoint> q{RPoint(0, 0), RPoint(0, 0), RPoint(3, 4), RPoint(3, 4), RPoint(3, 0), RPoint(0, 0)};
        const auto quartic = fitBezierExact(q, 4, Parametrization::ChordLength);
        QVERIFY(!quartic.ok());
        QCOMPARE(quartic.error().code, ErrorCode::Singular);
        const auto cubic = fitBezierExact(q, 3, Parametrization::ChordLength);
        QVERIFY(cubic.ok());
        QCOMPARE(cubic->params, (std::vector<Rational>{R("0"), R("0"), R("5/12"), R("5/12"), R("3/4"), R("1")}));
        for (LeastSquaresSolver s : kSolvers) {
            const auto fit = fitBezier(toDouble(q), options(3, Parametrization::ChordLength, s));
            QVERIFY(fit.ok());
            QVERIFY(maxAbs(toMatrix(fit->controlPoints) - cubic->P.toDouble()) <= 1e-12);
        }
    }

    void allPointsCoincide_data()
    {
        QTest::addColumn<Parametrization>("parametrization");
        QTest::addColumn<LeastSquaresSolver>("solver");
        for (Parametrization p : kParametrizations)
            for (LeastSquaresSolver s : kSolvers)
                QTest::addRow("%s %s", toString(p).c_str(), toString(s).c_str()) << p << s;
    }
    void allPointsCoincide()
    {
        QFETCH(Parametrization, parametrization);
        QFETCH(LeastSquaresSolver, solver);
        const Point point(2.5, -1.25);
        const std::vector<Point> q(6, point);
        bool fellBack = false;
        const std::vector<double> t = parameters(q, parametrization, &fellBack),
                                  uniform = parameters(q, Parametrization::Uniform);
        if (parametrization == Parametrization::AnnexIII) {
            // Annex III measures from the origin: equal |Q_j| ≠ 0 give uniform steps, no fallback.
            QVERIFY(!fellBack);
            for (std::size_t i = 0; i < t.size(); ++i)
                QVERIFY(std::fabs(t[i] - uniform[i]) <= 1e-15);
        } else {
            QCOMPARE(t, uniform);
            QCOMPARE(fellBack, parametrization != Parametrization::Uniform);
        }
        for (int degree = 0; degree <= 5; ++degree) {
            const auto fit = fitBezier(q, options(degree, parametrization, solver));
            QVERIFY(fit.ok());
            QVERIFY(allFinite(*fit));
            for (const Point& p : fit->controlPoints)
                QVERIFY(norm(p - point) <= 1e-14);
            QCOMPARE(fit->sse, 0.0);
            QCOMPARE(hasWarning(*fit, "coincide"), fellBack); // the parameters fell back to uniform: said
        }
    }

    void collinearData_data()
    {
        QTest::addColumn<Parametrization>("parametrization");
        QTest::addColumn<LeastSquaresSolver>("solver");
        for (Parametrization p : kParametrizations)
            for (LeastSquaresSolver s : kSolvers)
                QTest::addRow("%s %s", toString(p).c_str(), toString(s).c_str()) << p << s;
    }
    void collinearData()
    {
        QFETCH(Parametrization, parametrization);
        QFETCH(LeastSquaresSolver, solver);
        // Points on y = 2x + 1, unevenly spaced and running back and forth.
        std::vector<Point> q;
        for (int i = 0; i < 12; ++i) {
            const double x = 0.1 * i * i - 0.9 * i;
            q.emplace_back(x, 2 * x + 1);
        }
        const Point direction(1 / std::sqrt(5.0), 2 / std::sqrt(5.0));
        for (int degree = 1; degree <= 5; ++degree) {
            const auto fit = fitBezier(q, options(degree, parametrization, solver));
            QVERIFY(fit.ok());
            QVERIFY(allFinite(*fit));
            // The control points lie on the same line (the curve is in their convex hull).
            for (const Point& p : fit->controlPoints)
                QVERIFY(std::fabs(cross(p - Point(0, 1), direction)) <= 1e-10);
            for (const Point& r : fit->residuals)
                QVERIFY(std::fabs(cross(r, direction)) <= 1e-10);
        }
    }

    void extremeCoordinates_data()
    {
        QTest::addColumn<double>("scale");
        QTest::addColumn<double>("offset");
        QTest::addColumn<double>("tolerance"); // relative to the scale of the data
        QTest::newRow("1e9") << 1e9 << 0.0 << 1e-12;
        QTest::newRow("1e-9") << 1e-9 << 0.0 << 1e-12;
        QTest::newRow("1e-9 at 1e-9") << 1e-9 << 1e-9 << 1e-12;
        // Around 1e9 a double resolves 1.2e−7: that is all the data carry.
        QTest::newRow("unit size at 1e9") << 1.0 << 1e9 << 1e-5;
        QTest::newRow("1e3 at 1e9") << 1e3 << 1e9 << 1e-8;
    }
    void extremeCoordinates()
    {
        QFETCH(double, scale);
        QFETCH(double, offset);
        QFETCH(double, tolerance);
        const std::vector<Point> base = randomPoints(40, 99, 1.0);
        std::vector<Point> q;
        for (const Point& p : base)
            q.emplace_back(scale * p.x + offset, scale * p.y - offset);
        for (Parametrization p : kParametrizations)
            for (LeastSquaresSolver s : kSolvers) {
                if (p == Parametrization::AnnexIII && offset != 0)
                    continue; // measured from the origin, Annex III's t change with a shift: its slip
                const auto reference = fitBezier(base, options(5, p, s));
                const auto fit = fitBezier(q, options(5, p, s));
                QVERIFY(reference.ok());
                QVERIFY(fit.ok());
                QVERIFY(allFinite(*fit));
                double error = 0;
                for (std::size_t j = 0; j < fit->controlPoints.size(); ++j) {
                    const Point expected(scale * reference->controlPoints[j].x + offset,
                                         scale * reference->controlPoints[j].y - offset);
                    error = std::max(error, norm(fit->controlPoints[j] - expected) / scale);
                }
                QVERIFY2(error <= tolerance,
                         qPrintable(QString("%1 %2: error %3 × scale")
                                        .arg(QString::fromStdString(toString(p)), QString::fromStdString(toString(s)))
                                        .arg(error)));
                if (offset == 0)
                    QVERIFY(std::fabs(fit->sse / (scale * scale) - reference->sse) <= 1e-12 * reference->sse);
            }
    }

    void degree60WarnsButStaysFinite()
    {
        const std::vector<Point> q = smoothSamples(200, 1e-3);
        for (LeastSquaresSolver s : kSolvers) {
            const auto fit = fitBezier(q, options(60, Parametrization::Uniform, s));
            if (!fit) {
                // Only the normal equations may give up, and then with a reason.
                QVERIFY(s == LeastSquaresSolver::Normal);
                QCOMPARE(fit.error().code, ErrorCode::Singular);
                qInfo("degree 60, normal equations: %s", fit.error().message.c_str());
                continue;
            }
            QVERIFY(allFinite(*fit));
            QCOMPARE(fit->controlPoints.size(), std::size_t(61));
            QVERIFY(fit->cond > 1e10);
            QVERIFY2(hasWarning(*fit, "ill-conditioned"), qPrintable(warnings(*fit)));
            QVERIFY(fit->rms < 1e-3); // the noise level: the curve still follows the data
            qInfo("degree 60, %s: cond2(M) = %.3g, rms = %.3g; %s", toString(s).c_str(), fit->cond, fit->rms,
                  qPrintable(warnings(*fit)));
        }
    }

    void millionPoints()
    {
        const int count = 1000000;
        std::vector<Point> q;
        q.reserve(count);
        for (int i = 0; i < count; ++i) {
            const double s = static_cast<double>(i) / (count - 1);
            q.emplace_back(std::cos(3 * s) + 0.5 * s + 1e-3 * std::sin(1e4 * s), std::sin(2 * s));
        }
        QElapsedTimer clock;
        clock.start();
        const auto fit = fitBezier(q, options(10, Parametrization::ChordLength));
        const qint64 ms = clock.elapsed();
        QVERIFY(fit.ok());
        QVERIFY(allFinite(*fit));
        QCOMPARE(fit->residuals.size(), std::size_t(count));
        QVERIFY(fit->rms < 1e-3); // the 1e−3 ripple is all that is left
        qInfo("10^6 points, degree 10: %lld ms, cond2(M) = %.3g, rms = %.3g", static_cast<long long>(ms), fit->cond, fit->rms);
    }

    // ── Iterative parameter correction (beyond the thesis) ─────────────────────────────

    void correctionImprovesChordLength_data()
    {
        QTest::addColumn<LeastSquaresSolver>("solver");
        for (LeastSquaresSolver s : kSolvers)
            QTest::addRow("%s", toString(s).c_str()) << s;
    }
    void correctionImprovesChordLength()
    {
        QFETCH(LeastSquaresSolver, solver);
        // A cubic whose speed varies a lot, sampled at uniform t: chord length misplaces
        // the parameters, so even the right degree leaves a clear error.
        const std::vector<Point> P{Point(0, 0), Point(0.5, 3), Point(1, -3), Point(10, 1)};
        std::vector<Point> q;
        for (int i = 0; i < 40; ++i) {
            const double t = i / 39.0, u = 1 - t;
            q.push_back(Point(u * u * u * P[0].x + 3 * u * u * t * P[1].x + 3 * u * t * t * P[2].x + t * t * t * P[3].x,
                              u * u * u * P[0].y + 3 * u * u * t * P[1].y + 3 * u * t * t * P[2].y + t * t * t * P[3].y));
        }
        FitOptions o = options(3, Parametrization::ChordLength, solver);
        const auto plain = fitBezier(q, o);
        QVERIFY(plain.ok());
        o.correctParameters = true;
        const auto corrected = fitBezier(q, o);
        QVERIFY(corrected.ok());
        QVERIFY(allFinite(*corrected));
        QVERIFY(corrected->corrections >= 1);
        QVERIFY(corrected->corrections <= o.maxCorrections);
        QVERIFY(corrected->sse < 0.75 * plain->sse);
        for (double t : corrected->params)
            QVERIFY(t >= 0 && t <= 1);
        // The reported error belongs to the reported parameters.
        QVERIFY(normalEquationDefect(q, *corrected) <= 1e-10);
        qInfo("%s: SSE %.3g with chord length, %.3g after %d corrections", toString(solver).c_str(), plain->sse, corrected->sse,
              corrected->corrections);
        // Projecting and refitting converges only linearly, but it does converge: the
        // samples lie on a cubic, so enough corrections recover it.
        o.maxCorrections = 1000;
        const auto many = fitBezier(q, o);
        QVERIFY(many.ok());
        QVERIFY(many->corrections > corrected->corrections);
        QVERIFY(many->sse < 1e-8 * plain->sse);
        qInfo("%s: SSE %.3g after %d corrections", toString(solver).c_str(), many->sse, many->corrections);
        // maxCorrections = 0 is the plain fit.
        o.maxCorrections = 0;
        const auto none = fitBezier(q, o);
        QCOMPARE(none->corrections, 0);
        QCOMPARE(none->sse, plain->sse);
    }

    void correctionNeverIncreasesError_data() { leastSquaresOptimality_data(); }
    void correctionNeverIncreasesError()
    {
        QFETCH(Parametrization, parametrization);
        QFETCH(LeastSquaresSolver, solver);
        for (std::uint64_t seed = 11; seed <= 13; ++seed) {
            const std::vector<Point> q = randomPoints(15, seed);
            for (int degree : {1, 2, 4}) {
                FitOptions o = options(degree, parametrization, solver);
                const auto plain = fitBezier(q, o);
                o.correctParameters = true;
                o.maxCorrections = 10;
                const auto corrected = fitBezier(q, o);
                QVERIFY(plain.ok());
                QVERIFY(corrected.ok());
                QVERIFY(allFinite(*corrected));
                QVERIFY(corrected->sse <= plain->sse);
                QVERIFY(corrected->corrections <= 10);
            }
        }
    }
};

GRANOTA_TEST_GUILESS_MAIN(TestLeastSquaresFit)
#include "test_least_squares_fit.moc"
