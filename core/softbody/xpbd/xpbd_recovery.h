#pragma once
/// \file xpbd_recovery.h
/// Recovery of a body that has turned inside out (signed area of the wrong sign), been
/// squashed flat or tangled into itself: shape matching (Müller, Heidelberger, Teschner and
/// Gross 2005, "Meshless deformations based on shape matching"). The rest shape is rotated
/// to fit the current vertices as well as possible and placed on their centroid; the goal
/// positions it gives form a valid body by construction (a rotation cannot mirror), and
/// the vertices are pulled towards them until the body is valid again.

#include "core/base/vec2.h"
#include "core/softbody/polygon_geometry.h" // vertexCentroid

namespace granota {

/// The rotation angle R(θ) that best maps the centred rest shape onto x − centroid:
/// the rotation part of A_pq = Σ (xᵢ − c) restᵢᵀ (Müller et al. 2005, eq. 7), which in 2D
/// has the closed form θ = atan2(A₂₁ − A₁₂, A₁₁ + A₂₂) (the polar decomposition of a 2×2
/// matrix). Radians, counter-clockwise in the x–y frame (clockwise on screen).
double bestFitRotation(const Point* x, const Point* rest, int n, const Point& centroid);

/// Does any pair of non-adjacent edges of the closed polygon cross?
bool polygonSelfIntersects(const Point* x, int n);

/// Moves each vertex the share `rate` of the way to its goal c + R·restᵢ (eq. 3 with α = rate).
void shapeMatchingPull(Point* x, const Point* rest, int n, double rate);

} // namespace granota
