#include "ui/fit/fit_view_bounds.h"

#include "core/base/aabb.h"

#include "ui/common/curvature_comb.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace granota::ui {

namespace {

QRectF boundsOf(const std::vector<Point>& a, const std::vector<Point>& b)
{
    const std::optional<Aabb> box = finiteBox(a, b);
    if (!box)
        return QRectF(-1, -1, 2, 2);
    double w = box->width(), h = box->height();
    const double size = std::max({w, h, std::fabs(box->minX) * 1e-12, std::fabs(box->minY) * 1e-12, 1e-300});
    if (w < size * 1e-3)
        w = size * 1e-3;
    if (h < size * 1e-3)
        h = size * 1e-3;
    const double cx = 0.5 * box->minX + 0.5 * box->maxX, cy = 0.5 * box->minY + 0.5 * box->maxY;
    return QRectF(cx - 0.5 * w, cy - 0.5 * h, w, h);
}

} // namespace

QRectF fitViewBounds(const std::vector<Point>& data, const std::vector<Point>& curve, const std::vector<Point>* controlPoints,
                     const CurvatureComb* comb)
{
    const QRectF inner = boundsOf(data, curve);
    QRectF bounds = inner;
    if (controlPoints) {
        const QRectF control = boundsOf(*controlPoints, {});
        const double size = std::max(inner.width(), inner.height());
        const double reach = kControlPointReach * size;
        if (inner.adjusted(-reach, -reach, reach, reach).contains(control))
            bounds = bounds.united(control);
    }
    if (comb && !comb->empty()) {
        std::vector<Point> tips;
        for (const CurvatureComb::Tooth& tooth : comb->teeth)
            tips.push_back(tooth.tip);
        bounds = bounds.united(boundsOf(tips, {}));
    }
    return bounds;
}

} // namespace granota::ui
