#include "simcore/geometry/MeshMapping.h"

#include "simcore/geometry/TriangleGrid.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

namespace colonosim::geometry {

namespace {

struct Solve {
    bool converged = false;
    Eigen::Vector3d weight = Eigen::Vector3d::Zero();
    double offset = 0.0;
    double residual = 0.0;
};

/// Newton's method on F(u, w, d) = x0 + u e1 + w e2 + d n(u, w) - v.
Solve solveBinding(const Eigen::Vector3d& v, const std::array<Eigen::Vector3d, 3>& x,
                   const std::array<Eigen::Vector3d, 3>& n, const Eigen::Vector3d& startBary)
{
    const Eigen::Vector3d e1 = x[1] - x[0];
    const Eigen::Vector3d e2 = x[2] - x[0];
    double u = startBary.y();
    double w = startBary.z();
    Eigen::Vector3d blended = n[0] + u * (n[1] - n[0]) + w * (n[2] - n[0]);
    double d = (v - (x[0] + u * e1 + w * e2)).dot(blended.normalized());
    Solve out;
    for (int it = 0; it < 30; ++it) {
        blended = n[0] + u * (n[1] - n[0]) + w * (n[2] - n[0]);
        const double len = blended.norm();
        if (len < 1e-12 || !std::isfinite(len)) {
            return out;
        }
        const Eigen::Vector3d nh = blended / len;
        const Eigen::Vector3d f = x[0] + u * e1 + w * e2 + d * nh - v;
        out.residual = f.norm();
        if (out.residual < 1e-14) {
            out.converged = true;
            break;
        }
        const Eigen::Matrix3d project = (Eigen::Matrix3d::Identity() - nh * nh.transpose()) / len;
        Eigen::Matrix3d jac;
        jac.col(0) = e1 + d * project * (n[1] - n[0]);
        jac.col(1) = e2 + d * project * (n[2] - n[0]);
        jac.col(2) = nh;
        const Eigen::Vector3d step = jac.partialPivLu().solve(-f);
        if (!step.allFinite()) {
            return out;
        }
        u += step.x();
        w += step.y();
        d += step.z();
        out.converged = step.norm() < 1e-15;
    }
    if (!out.converged) {
        // Newton stalls at rounding level: accept a residual below 1e-12 m.
        out.converged = out.residual < 1e-12;
    }
    out.weight = Eigen::Vector3d(1.0 - u - w, u, w);
    out.offset = d;
    return out;
}

}  // namespace

MeshMapping::MeshMapping(const TriangleMesh& physicsRest, const Eigen::Matrix3Xd& visualRest)
    : m_visualRest(visualRest)
{
    if (physicsRest.numTriangles() == 0 || visualRest.cols() == 0) {
        throw std::invalid_argument("MeshMapping: physics mesh has " +
                                    std::to_string(physicsRest.numTriangles()) +
                                    " triangles and visual mesh " + std::to_string(visualRest.cols()) +
                                    " vertices (allowed: both > 0)");
    }
    m_bindings.resize(static_cast<std::size_t>(visualRest.cols()));
    std::vector<int> all(m_bindings.size());
    std::iota(all.begin(), all.end(), 0);
    bindVertices(all, physicsRest);
}

void MeshMapping::remap(std::span<const int> visualVertices, const TriangleMesh& physicsRest)
{
    bindVertices(visualVertices, physicsRest);
}

void MeshMapping::computeVertexNormals(const Eigen::Matrix3Xd& x,
                                       const std::vector<std::array<int, 3>>& triangles,
                                       Eigen::Matrix3Xd& normals)
{
    if (normals.cols() != x.cols()) {
        normals.resize(3, x.cols());
    }
    normals.setZero();
    for (const auto& t : triangles) {
        // |cross| is twice the area, so the sum is area-weighted.
        const Eigen::Vector3d x0 = x.col(t[0]);
        const Eigen::Vector3d faceNormal = (x.col(t[1]) - x0).cross(x.col(t[2]) - x0);
        normals.col(t[0]) += faceNormal;
        normals.col(t[1]) += faceNormal;
        normals.col(t[2]) += faceNormal;
    }
    for (Eigen::Index i = 0; i < normals.cols(); ++i) {
        const double len = normals.col(i).norm();
        if (len > 0.0) {
            normals.col(i) /= len;
        }
    }
}

void MeshMapping::bindVertices(std::span<const int> visualVertices, const TriangleMesh& physicsRest)
{
    m_triangles = physicsRest.triangles;
    Eigen::Matrix3Xd normals;
    computeVertexNormals(physicsRest.vertices, m_triangles, normals);
    const TriangleGrid grid(physicsRest);
    std::vector<TriangleGrid::Candidate> candidates;
    const double slack = 0.5 * grid.cellSize();
    for (int vi : visualVertices) {
        const Eigen::Vector3d v = m_visualRest.col(vi);
        grid.nearest(v, slack, candidates);
        Solve best;
        double bestOutside = std::numeric_limits<double>::infinity();
        std::array<int, 3> bestNodes{};
        for (const auto& candidate : candidates) {
            const auto& t = m_triangles[static_cast<std::size_t>(candidate.triangle)];
            const std::array<Eigen::Vector3d, 3> x{physicsRest.vertices.col(t[0]),
                                                   physicsRest.vertices.col(t[1]),
                                                   physicsRest.vertices.col(t[2])};
            const std::array<Eigen::Vector3d, 3> n{normals.col(t[0]), normals.col(t[1]), normals.col(t[2])};
            Eigen::Vector3d bary;
            closestPointOnTriangle(v, x[0], x[1], x[2], &bary);
            const Solve solve = solveBinding(v, x, n, bary);
            if (!solve.converged) {
                continue;
            }
            const double outside = std::max(0.0, -solve.weight.minCoeff());
            if (outside < bestOutside) {
                best = solve;
                bestOutside = outside;
                bestNodes = t;
            }
            if (outside <= 1e-9) {
                break;
            }
        }
        if (!best.converged) {
            // No smooth-normal solution: fall back to the nearest point and the face normal.
            const auto& t = m_triangles[static_cast<std::size_t>(candidates.front().triangle)];
            Eigen::Vector3d bary;
            const Eigen::Vector3d q =
                closestPointOnTriangle(v, physicsRest.vertices.col(t[0]), physicsRest.vertices.col(t[1]),
                                       physicsRest.vertices.col(t[2]), &bary);
            best.weight = bary;
            const Eigen::Vector3d nb =
                (bary.x() * normals.col(t[0]) + bary.y() * normals.col(t[1]) + bary.z() * normals.col(t[2]))
                    .normalized();
            best.offset = (v - q).dot(nb);
            best.residual = (v - q - best.offset * nb).norm();
            bestNodes = t;
        }
        m_bindings[static_cast<std::size_t>(vi)] = {bestNodes, best.weight, best.offset};
        m_maxRestResidual = std::max(m_maxRestResidual, best.residual);
    }
    m_normals.resize(3, physicsRest.vertices.cols());
}

void MeshMapping::apply(const Eigen::Matrix3Xd& physicsPositions, Eigen::Matrix3Xd& visualOut) const
{
    computeVertexNormals(physicsPositions, m_triangles, m_normals);
    if (visualOut.cols() != static_cast<Eigen::Index>(m_bindings.size())) {
        visualOut.resize(3, static_cast<Eigen::Index>(m_bindings.size()));
    }
    const double* x = physicsPositions.data();
    const double* n = m_normals.data();
    double* out = visualOut.data();
    const std::size_t numBindings = m_bindings.size();
    for (std::size_t i = 0; i < numBindings; ++i) {
        const Binding& b = m_bindings[i];
        const double* x0 = x + 3 * b.node[0];
        const double* x1 = x + 3 * b.node[1];
        const double* x2 = x + 3 * b.node[2];
        const double* n0 = n + 3 * b.node[0];
        const double* n1 = n + 3 * b.node[1];
        const double* n2 = n + 3 * b.node[2];
        const double w0 = b.weight.x();
        const double w1 = b.weight.y();
        const double w2 = b.weight.z();
        double p[3];
        double m[3];
        for (int k = 0; k < 3; ++k) {
            p[k] = w0 * x0[k] + w1 * x1[k] + w2 * x2[k];
            m[k] = w0 * n0[k] + w1 * n1[k] + w2 * n2[k];
        }
        const double scale = b.offset / std::sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
        out[3 * i] = p[0] + scale * m[0];
        out[3 * i + 1] = p[1] + scale * m[1];
        out[3 * i + 2] = p[2] + scale * m[2];
    }
}

}  // namespace colonosim::geometry
