// granota-cli spline --monotone: monotone cubic interpolation of function data
// (core/curves/splines/monotone_spline.h), each piece in powers of x, with the proof of each
// piece's monotonicity from its Bernstein coefficients.
#include "app/cli/finite_doubles.h"
#include "app/cli/spline_modes.h"

#include "core/curves/splines/monotone_spline.h"

namespace granota::cli {

namespace {
const char* verdictName(PieceMonotonicity v)
{
    switch (v) {
    case PieceMonotonicity::Constant: return "constant";
    case PieceMonotonicity::Increasing: return "increasing";
    case PieceMonotonicity::Decreasing: return "decreasing";
    case PieceMonotonicity::NotMonotone: break;
    }
    return "not monotone";
}
} // namespace

Expected<CommandOutput> runMonotoneSpline(const Arguments& args)
{
    auto points = args.points();
    if (!points)
        return points.error();
    auto methodName = args.choice("monotone", {"fritsch-carlson", "steffen"}, std::nullopt);
    if (!methodName)
        return methodName.error();
    for (const char* option : {"ends", "start-slope", "end-slope", "param", "start-tangent", "end-tangent", "exact"})
        if (args.has(option))
            return makeError(ErrorCode::InvalidInput, std::string("--") + option + " is not an option of --monotone");
    auto data = finiteDoubles(*points, false);
    if (!data)
        return data.error();
    const MonotoneMethod method = *parseMonotoneMethod(*methodName);
    auto slopes = monotoneSlopes(*data, method);
    if (!slopes)
        return slopes.error().code == ErrorCode::OutOfRange ? tooLargeForDouble("the monotone spline of these points", false)
                                                            : slopes.error();
    auto spline = monotoneSpline(*data, method);
    if (!spline)
        return spline.error().code == ErrorCode::OutOfRange ? tooLargeForDouble("the monotone spline of these points", false)
                                                            : spline.error();
    CommandOutput out;
    std::ostringstream txt;
    txt << "Monotone cubic interpolation (" << *methodName << "), C¹; pieces in powers of x:\n";
    out.json.set("monotone", *methodName);
    describePieces(*spline, false, out, txt);
    Json verdicts = Json::array();
    txt << "Each piece, proven from its Bernstein coefficients:";
    for (const MonotonePieceProof& proof : proveMonotone(*data, *slopes)) {
        verdicts.push(Json(std::string(verdictName(proof.verdict))));
        txt << " " << verdictName(proof.verdict);
    }
    txt << "\n";
    out.json.set("monotonicity", std::move(verdicts));
    out.text = txt.str();
    return out;
}

} // namespace granota::cli
