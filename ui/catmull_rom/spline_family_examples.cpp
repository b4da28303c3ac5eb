#include "ui/catmull_rom/spline_family_examples.h"

#include "core/softbody/regular_polygon.h"
#include "core/softbody/scenes/frog_params.h"

namespace granota::ui {

std::vector<Point> frogOutlineExamplePoints()
{
    const FrogParams frog;
    // regularPolygon starts at the top in screen coordinates (y down): turn y up for the canvas.
    std::vector<Point> points = regularPolygon(Point(0, 0), frog.radius, frog.sides);
    for (Point& p : points)
        p.y = -p.y;
    return points;
}

std::vector<Point> d3Shape38ExamplePoints()
{
    return {{0, 224}, {100, 200}, {107, 180}, {502, 300}, {580, 120}, {607, 148}, {900, 400}};
}

} // namespace granota::ui
