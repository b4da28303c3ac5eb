#include "ui/fit/fit_export.h"

#include "core/base/number_format.h"
#include "core/curves/fitting/fit_error_by_degree.h"
#include "ui/fit/fit_error_plot.h"
#include "ui/files/tikz_writer.h"

namespace granota::ui {

QString fitCsv(const FitCsvInput& in)
{
    const std::vector<Point>& q = in.data;
    // At most 15 significant digits: the data as typed, the fit without binary noise
    // (0.157142857142857, not 0.15714285714285747 beside the panel's 11/70).
    const auto f = [](double v) { return QString::fromStdString(formatReadable(v)); };
    QString out = QStringLiteral("i,x,y,t,alpha_x,alpha_y,residual_x,residual_y\n");
    out.reserve(static_cast<qsizetype>(q.size()) * 160);
    const bool fitted = in.fit && in.fit->residuals.size() == q.size();
    const auto exactText = [&in](std::size_t i, bool x) {
        const Point& p = in.data[i];
        if (in.exact.size() != in.data.size())
            return QString::fromStdString(formatReadable(x ? p.x : p.y));
        return QString::fromStdString(x ? readableExact(in.exact[i].x, p.x) : readableExact(in.exact[i].y, p.y));
    };
    for (std::size_t i = 0; i < q.size(); ++i) {
        out += QStringLiteral("%1,%2,%3").arg(i).arg(exactText(i, true), exactText(i, false));
        if (fitted) {
            const Point r = in.fit->residuals[i];
            const Point a = q[i] - r;
            out += QStringLiteral(",%1,%2,%3,%4,%5").arg(f(in.fit->params[i]), f(a.x), f(a.y), f(r.x), f(r.y));
        } else {
            out += QStringLiteral(",,,,,");
        }
        out += QLatin1Char('\n');
    }
    if (fitted) {
        out += QStringLiteral("\nj,P_x,P_y\n");
        for (std::size_t j = 0; j < in.fit->controlPoints.size(); ++j)
            out += QStringLiteral("%1,%2,%3\n").arg(j).arg(f(in.fit->controlPoints[j].x), f(in.fit->controlPoints[j].y));
    }
    if (in.allParametrizations) {
        // The error plot's lines, as fitErrorByDegree gives them (empty where that fit failed).
        out += QStringLiteral("\nparametrization,degree,sse\n");
        FitOptions options;
        options.solver = in.solver;
        for (Parametrization p : kPlottedParametrizations) {
            options.parametrization = p;
            for (const DegreeError& e : fitErrorByDegree(q, options, in.lastDegree))
                out += QStringLiteral("%1,%2,%3\n")
                           .arg(QString::fromStdString(toString(p)))
                           .arg(e.degree)
                           .arg(e.ok ? f(e.sse) : QString());
        }
    }
    return out;
}

void writeFitFigureTikz(TikzWriter& tikz, int degree, Parametrization parametrization, const FitPicture& picture,
                        const CurvatureComb* comb)
{
    tikz.comment(QStringLiteral("Granota: least-squares Bézier fit of degree %1 (%2 parameters), %3 data points")
                     .arg(degree)
                     .arg(QString::fromStdString(toString(parametrization)))
                     .arg(picture.data.size()));
    writeFitTikz(tikz, picture, comb);
}

} // namespace granota::ui
