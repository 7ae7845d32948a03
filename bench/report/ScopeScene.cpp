#include "bench/report/ScopeScene.h"

#include <algorithm>
#include <cmath>

namespace colonosim::bench {

namespace {

/// The side forces sit on every kLoadSpacing-th node of a kLoadGridNodes-node scope.
constexpr int kLoadGridNodes = 80;
constexpr int kLoadSpacing = 5;

void addNodeForce(scope::Colonoscope& scope, int node, const Eigen::Vector3d& force)
{
    scope.setNodeForce(node, scope.rod().force[static_cast<size_t>(node)] + force);
}

}  // namespace

scope::Colonoscope realisticScope(const scope::ScopeParameters& parameters)
{
    scope::Colonoscope result(parameters);
    result.setHandlePose(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitZ());
    result.setInsertion(kBenchScopeInsertion);
    result.setDials(0.6, -0.2);
    result.setShaftRotation(0.3);
    return result;
}

void applyContactLoads(scope::Colonoscope& scope, ScopeLoad load)
{
    scope.clearLoads();
    if (load == ScopeLoad::Free) {
        scope.addGravity(Eigen::Vector3d(0.0, 0.0, -9.81));
    }
    const scope::DiscreteRod& rod = scope.rod();
    const int n = scope.numInsertedNodes();
    if (n < 2) {
        return;
    }
    const double inserted = rod.stubLength + (n - 1) * rod.elementLength;
    const double gridElement = scope.parameters().workingLength / (kLoadGridNodes - 1);
    const int gridNodes =
        std::min(kLoadGridNodes, static_cast<int>(std::floor(inserted / gridElement + 1e-9)) + 1);
    for (int g = kLoadSpacing; g < gridNodes - 1; g += kLoadSpacing) {
        // Nodes are material points counted from the tip: the grid node lies
        // `fromTip` elements of this scope from the tip, on the rigid element
        // between nodes `near` and near - 1; the lever rule splits its force
        // between them, which keeps its resultant and its moment about every point.
        const double fromTip = (gridNodes - 1 - g) * gridElement / rod.elementLength;
        const double whole = std::floor(fromTip + 1e-9);
        const double fraction = std::max(0.0, fromTip - whole);
        const int near = n - 1 - static_cast<int>(whole);
        const double side = 0.05 + 0.15 * std::abs(std::sin(0.3 * g));
        const Eigen::Vector3d force(-0.02, side * std::cos(0.7 * g), side * std::sin(0.7 * g));
        if (near <= 0) {
            addNodeForce(scope, 0, force);  // on the clamped stub: carried by the clamp
            continue;
        }
        addNodeForce(scope, near, (1.0 - fraction) * force);
        if (fraction > 1e-9) {
            addNodeForce(scope, near - 1, fraction * force);
        }
    }
    const double axialTip = load == ScopeLoad::Free ? -0.3 : 0.0;
    addNodeForce(scope, n - 1, Eigen::Vector3d(axialTip, 0.05, 0.0));
}

}  // namespace colonosim::bench
