#include "core/curves/splines/spline_offset_correction.h"

namespace granota {

OffsetCorrectionResult correctConstantOffsets(const PiecewisePolynomial<Rational>& spline, const std::vector<RPoint>& data)
{
    OffsetCorrectionResult result;
    result.corrected = spline;
    if (!spline.isValid() || data.size() != spline.knots.size())
        return result;
    for (std::size_t i = 0; i < data.size(); ++i)
        if (data[i].x != spline.knots[i])
            return result;
    for (int i = 0; i < spline.pieceCount(); ++i) {
        const auto a = static_cast<std::size_t>(i), b = a + 1;
        const Rational missLeft = data[a].y - spline.evaluatePiece(i, data[a].x);
        const Rational missRight = data[b].y - spline.evaluatePiece(i, data[b].x);
        if (missLeft != 0 && missLeft == missRight) {
            // A constant shift keeps the storage form: q(x) + c and q(x − x_i) + c alike.
            result.corrected.pieces[a] += Polynomial<Rational>(missLeft);
            result.corrections.push_back({i, missLeft});
        }
    }
    return result;
}

} // namespace granota
