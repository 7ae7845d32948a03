#pragma once
/// \file
/// The Laplace chart of a wall mesh (after the streamline parameterisation of
/// the CSIRO colonoscopy simulator, which solves Laplace's equation on the
/// colon surface for smooth texture coordinates without tearing).
///
/// Along-coordinate: the harmonic function u on the surface,
///   Laplace-Beltrami(u) = 0,  u = 0 on the open end at the centreline's
///   start (the anal ring),  u = 1 at the far end: the boundary loop near
///   the centreline's end if the mesh is open there, else the apex vertex
///   (the one furthest along the last tangent, the tip of the cecal dome),
/// discretised with the cotangent Laplacian, w_ij = (cot a_ij + cot b_ij) / 2
/// (Pinkall and Polthier 1993), negative edge weights clamped to 0 so the
/// discrete maximum principle holds and u has no interior extrema (no folds
/// of its level sets). Solved with a sparse LDL^T factorisation.
///
/// Metres: vertices sorted by u are grouped into levels of twice the anal
/// ring's vertex count (about two rings); each level's centroid is projected
/// onto the centreline (continued along its end tangents), which gives the
/// level's arc length s, made non-decreasing along u. A vertex's s is
/// interpolated linearly in u between level means, and its clock angle is
/// theta = atan2((v - c(s)).b(s), (v - c(s)).n(s)) in the centreline's
/// rotation-minimising frame at s. Stored as (s, r cos theta, r sin theta),
/// r the centreline radius at s (m), the layout of CentrelineChart.

#include "simcore/geometry/Centreline.h"
#include "simcore/geometry/TriangleMesh.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <vector>

namespace colonosim::render {

/// The harmonic along-coordinate u in [0, 1], one per vertex. Throws
/// std::invalid_argument when the mesh has no triangles or no open end
/// (boundary edge) nearer the centreline's start than its end, or when the
/// centreline has fewer than two samples.
[[nodiscard]] Eigen::VectorXd harmonicAlongCoordinate(const geometry::TriangleMesh& mesh,
                                                      const geometry::Centreline& centreline);

/// The chart above, 3 floats per vertex. Throws as harmonicAlongCoordinate.
[[nodiscard]] std::vector<float> laplaceChart(const geometry::TriangleMesh& mesh,
                                              const geometry::Centreline& centreline);

}  // namespace colonosim::render
