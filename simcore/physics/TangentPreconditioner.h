#pragma once
/// \file
/// A preconditioner for the static solver's tangent system (-K+) dx = f: the
/// matrix -K+ assembled over the integrated nodes and factored (sparse LDL^T).
///
/// The stiffness is only available as a product (TissueBody::stiffnessProduct),
/// so the matrix is recovered by probing (Curtis, Powell & Reid, J Inst Maths
/// Applics 1974): the nodes are coloured so that no two nodes of one colour
/// share a coupled neighbour (a distance-2 colouring of the graph of the
/// force terms' couplings, ForceTerm::addCouplings), and one product per
/// colour and axis gives every column block of that colour at once, because
/// each row's coupled nodes then have distinct colours. The matrix is
/// symmetrised and factored (the colouring and the factor's ordering are
/// kept from one build to the next). A term whose couplings are not declared
/// (the lumen's self-contact, ForceTerm::couplingsDeclared) is not probed: it
/// would mix the columns of a colour and make the matrix indefinite (on
/// generated seed 7, a colon through itself, the factorisation then failed
/// at every iteration after the first, and the Jacobi fallback took about
/// 2,600 conjugate-gradient iterations a Newton iteration; without the
/// contact, about 10). The conjugate gradients still multiply by the exact
/// operator, so leaving it out only adds an iteration or so per contact
/// pair, it does not change the solution.
///
/// On the default colon (1,873 integrated nodes) the Jacobi preconditioner
/// took 26,904 conjugate-gradient iterations over the 14 Newton iterations of
/// the procedure's start (3.1 s).

#include "simcore/physics/TissueBody.h"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <vector>

namespace colonosim::physics {

class TangentPreconditioner {
public:
    /// Probes and factors -K+ of `body` at its positions, over its
    /// integrated nodes. False (and apply() must not be used) when the
    /// factorisation fails: the probed matrix is not positive definite. The
    /// colouring and the factor's ordering are kept for the next build while
    /// the integrated nodes stay the same: only the probes and the numerical
    /// factorisation are done again.
    bool build(const TissueBody& body);

    /// z = (-K+)^-1 r on the integrated nodes of the body of the last
    /// build() (other columns of z are zero).
    void apply(const Eigen::Matrix3Xd& r, Eigen::Matrix3Xd& z) const;

    /// Colours of the last build (its stiffness products are three per colour).
    [[nodiscard]] int colours() const { return m_colours; }

private:
    void colour(const TissueBody& body);
    void probe(const TissueBody& body);

    std::vector<int> m_nodes;                  ///< the integrated nodes, in order
    std::vector<std::vector<int>> m_adjacent;  ///< coupled nodes, by index into m_nodes
    std::vector<int> m_colour;                 ///< by index into m_nodes
    std::vector<std::vector<int>> m_byColour;  ///< indices into m_nodes, per colour
    std::vector<Eigen::Triplet<double>> m_entries;
    Eigen::SparseMatrix<double> m_matrix;
    bool m_analysed = false;
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> m_factor;
    mutable Eigen::VectorXd m_rhs, m_solution;
    int m_colours = 0;
};

}  // namespace colonosim::physics
