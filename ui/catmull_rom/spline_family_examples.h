#pragma once
/// \file spline_family_examples.h
/// The examples of the families "C² spline in the plane" and "function data", beyond the
/// thesis's worked examples (those stay in resources/examples/chapter2.json):
///  - the frog's outline points: the body's vertices at rest (§4.1, the regular N-gon of
///    FrogParams), through which §4.12 draws a closed Catmull-Rom outline — here a closed C²
///    spline against it;
///  - d3-shape #38's data, where the natural spline overshoots by about 98.

#include "core/base/vec2.h"

#include <vector>

namespace granota::ui {

/// The frog body's N vertices at rest (FrogParams's sides and radius), centred on the origin,
/// y up, the first at the top.
std::vector<Point> frogOutlineExamplePoints();
/// [[0,224],[100,200],[107,180],[502,300],[580,120],[607,148],[900,400]].
std::vector<Point> d3Shape38ExamplePoints();

} // namespace granota::ui
