// Whether a cube holds a point at distance >= 1 from every given centre: the
// exact test of last resort for the finest voxels of random sequential
// addition, which can no longer be refined.
//
// The distance to the nearest centre, d(p) = min_j |p - c_j|, restricted to
// the cube, is the largest at a vertex of the cube cut by the Voronoi
// diagram of the centres (within each Voronoi cell it is the distance to one
// centre, a convex function, so it peaks at a vertex of that convex piece).
// Those vertices are among: the cube's corners; the points of its edges
// equidistant from two centres; the points of its faces equidistant from
// three; the points inside equidistant from four. The cube holds a free point
// if and only if one of these candidates is free.
#pragma once
#include <span>

#include "simulate/engine/particles.h"

namespace coolgas {

// The cube is [lo, lo + side]^3; `centres` holds every centre whose
// exclusion sphere (radius 1) reaches into it, in the same frame.
bool holds_free_point(const Vec3& lo, double side, std::span<const Vec3> centres);

}  // namespace coolgas
