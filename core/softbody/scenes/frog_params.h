#pragma once
/// \file frog_params.h
/// The constants of the frog of Annex II ("Codi del programa Granota"), with the thesis's
/// names, shared by every scene and both solvers. Units are the seed's: pixels and
/// frames (one call of `actualitza()` is one step). Screen coordinates: y grows downwards.

#include "core/base/vec2.h"
#include "core/base/math_constants.h"

#include <array>

namespace granota {

/// One leg: the two segment lengths and the angle limits of Annex II (radians).
struct LegParams {
    double upper = 40;      ///< shoulder–elbow length (longit[..].x)
    double lower = 40;      ///< elbow–wrist length (longit[..].y)
    double shoulderMin = 0; ///< anglesc[..].x: minimum shoulder–elbow angle
    double shoulderMax = 0; ///< anglesc[..].y: maximum shoulder–elbow angle
    double elbowMin = 0;    ///< angles[..].x: minimum elbow–wrist angle
    double elbowMax = 0;    ///< angles[..].y: maximum elbow–wrist angle
};

struct FrogParams {
    Point gravity{0, 0.75};     ///< g (gravetat), px/step², added every step
    Point friction{0.95, 0.95}; ///< f (fregament), share of the velocity kept per step, per axis
    Point v0{0, -5};            ///< v0, initial velocity, px/step
    double areaFactor = 0.05;   ///< C (reescala), area correction factor
    int sides = 10;             ///< N (costats), vertices of the body
    double targetArea = 20000;  ///< Areal, target area, px²
    double springLength = 1;    ///< molls, rest length of every edge spring, px
    double velmax = 20;         ///< velmax, largest move of a vertex per step and per axis, px
    Point center{640, 360};     ///< centre of the first body, px
    double radius = 120;        ///< r, centre-to-vertex distance at rest (height/6), px
    double width = 1280;        ///< frame width, px (vertices stay in [0, width − 1])
    double height = 720;        ///< frame height, px (vertices stay in [0, height − 1])
    /// Front right, front left, back right, back left (the order of Annex II's arrays).
    std::array<LegParams, 4> legs{{
        {40, 40, 0, kPi, -kPi / 12, kPi / 12},
        {40, 40, -kPi, 0, -kPi / 12, kPi / 12},
        {80, 80, 0, kPi, -kPi / 3, kPi / 3},
        {80, 80, -kPi, 0, -kPi / 3, kPi / 3},
    }};
};

} // namespace granota
