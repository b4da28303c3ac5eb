#include "app/cli/command.h"

#include <string>

namespace granota::cli {

Expected<std::vector<RPoint>> controlPoints(const Arguments& args)
{
    auto points = args.points();
    if (!points)
        return points.error();
    if (static_cast<int>(points->size()) > kMaxDegree + 1)
        return makeError(ErrorCode::DegreeTooHigh, "at most " + std::to_string(kMaxDegree + 1) + " control points (degree " +
                                                       std::to_string(kMaxDegree) + ")");
    return points;
}

} // namespace granota::cli
