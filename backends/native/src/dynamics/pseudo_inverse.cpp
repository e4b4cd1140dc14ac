// SPDX-License-Identifier: MIT
#include "dynamics/pseudo_inverse.h"

#include <Eigen/QR>

namespace vroc::native {
namespace {

template <int N>
void pseudoInverseOfBlock(const Eigen::Matrix4d& m, Eigen::Matrix4d& inv) {
    const Eigen::Matrix<double, N, N> block = m.topLeftCorner<N, N>();
    inv.topLeftCorner<N, N>() =
        Eigen::CompleteOrthogonalDecomposition<Eigen::Matrix<double, N, N>>(block).pseudoInverse();
}

}  // namespace

void pseudoInverseInto(int n, const Eigen::Matrix4d& m, Eigen::Matrix4d& inv) {
    if (n == 2) pseudoInverseOfBlock<2>(m, inv);
    if (n == 3) pseudoInverseOfBlock<3>(m, inv);
    if (n == 4) pseudoInverseOfBlock<4>(m, inv);
}

}  // namespace vroc::native
