#include "core/exact/moore_penrose.h"

#include <Eigen/Eigenvalues>

namespace granota {

std::array<bool, 4> penroseConditions(const RationalMatrix& a, const RationalMatrix& aPlus)
{
    if (aPlus.rows() != a.cols() || aPlus.cols() != a.rows())
        return {false, false, false, false};
    const RationalMatrix aaPlus = a * aPlus, aPlusA = aPlus * a;
    return {aaPlus * a == a, aPlusA * aPlus == aPlus, aaPlus.transpose() == aaPlus, aPlusA.transpose() == aPlusA};
}

RationalMatrix leastSquaresHessian(const RationalMatrix& m)
{
    RationalMatrix h = m.transpose() * m;
    for (int r = 0; r < h.rows(); ++r)
        for (int c = 0; c < h.cols(); ++c)
            h(r, c) *= 2;
    return h;
}

std::vector<double> symmetricEigenvalues(const RationalMatrix& s)
{
    Eigen::MatrixXd d(s.rows(), s.cols());
    for (int r = 0; r < s.rows(); ++r)
        for (int c = 0; c < s.cols(); ++c)
            d(r, c) = toDouble(s(r, c));
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(d, Eigen::EigenvaluesOnly);
    std::vector<double> out(static_cast<std::size_t>(solver.eigenvalues().size()));
    for (Eigen::Index i = 0; i < solver.eigenvalues().size(); ++i)
        out[static_cast<std::size_t>(i)] = solver.eigenvalues()(i);
    return out;
}

} // namespace granota
