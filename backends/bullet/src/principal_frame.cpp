// SPDX-License-Identifier: MIT
#include "principal_frame.h"

#include <Eigen/Eigenvalues>
#include <cmath>

namespace vroc::bullet {

PrincipalFrame principalFrame(const MassProperties& props) {
    PrincipalFrame f;
    f.body_to_com.position = props.center_of_mass;
    const Mat3& I = props.inertia;
    const double scale = I.diagonal().cwiseAbs().maxCoeff();
    const double off = std::abs(I(0, 1)) + std::abs(I(0, 2)) + std::abs(I(1, 2));
    // Exactly (to round-off) diagonal: keep the body axes, so no spurious axis permutation.
    if (off <= 1e-14 * scale) {
        f.principal_inertia = I.diagonal();
        return f;
    }
    Eigen::SelfAdjointEigenSolver<Mat3> solver(0.5 * (I + I.transpose()));
    Mat3 axes = solver.eigenvectors();   // columns: principal axes in body coordinates
    if (axes.determinant() < 0) axes.col(2) = -axes.col(2);
    f.body_to_com.orientation = Quat(axes).normalized();
    f.principal_inertia = solver.eigenvalues();
    return f;
}

}  // namespace vroc::bullet
