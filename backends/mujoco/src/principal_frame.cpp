// SPDX-License-Identifier: MIT
#include "principal_frame.h"

#include <Eigen/Eigenvalues>
#include <cmath>

namespace vroc::mujoco {

PrincipalFrame principalFrame(const MassProperties& props) {
    PrincipalFrame f;
    f.com_in_body.position = props.center_of_mass;
    const Mat3& I = props.inertia;
    const double scale = I.diagonal().cwiseAbs().maxCoeff();
    const double off_diagonal = std::abs(I(0, 1)) + std::abs(I(0, 2)) + std::abs(I(1, 2));
    if (off_diagonal <= 1e-14 * scale) {
        f.principal_inertia = I.diagonal();
        return f;
    }
    Eigen::SelfAdjointEigenSolver<Mat3> solver(0.5 * (I + I.transpose()));
    Mat3 axes = solver.eigenvectors();   // columns: principal axes in body coordinates
    if (axes.determinant() < 0) axes.col(2) = -axes.col(2);
    f.com_in_body.orientation = Quat(axes).normalized();
    f.principal_inertia = solver.eigenvalues();
    return f;
}

}  // namespace vroc::mujoco
