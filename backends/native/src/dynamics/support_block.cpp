// SPDX-License-Identifier: MIT
#include "dynamics/support_block.h"

#include <cmath>

namespace vroc::native {

bool SupportBlock::factor(const SupportRow* rows, int count, double inv_mass, const Mat3& inv_inertia) {
    count_ = 0;
    if (count < 1 || count > kMaxSupportRows || !(inv_mass > 0.0)) return false;
    Eigen::Matrix<double, 6, 6> h = Eigen::Matrix<double, 6, 6>::Zero();
    for (int i = 0; i < count; ++i) {
        Eigen::Matrix<double, 6, 1> w;
        w << rows[i].linear, rows[i].angular;
        h.noalias() += w * w.transpose();
    }
    // The linear and the angular blocks have their own units (1 and m^2): H is factored scaled to a
    // unit diagonal trace per block, H = S^-1 (S H S) S^-1, so that the rank test (rows that leave
    // a direction of motion free make it singular) judges each block against its own scale.
    const double linear_scale = h.topLeftCorner<3, 3>().trace();
    const double angular_scale = h.bottomRightCorner<3, 3>().trace();
    if (!(linear_scale > 0.0) || !(angular_scale > 0.0)) return false;
    scale_ << Vec3::Constant(1.0 / std::sqrt(linear_scale)), Vec3::Constant(1.0 / std::sqrt(angular_scale));
    h_.compute(scale_.asDiagonal() * h * scale_.asDiagonal());
    if (h_.info() != Eigen::Success) return false;
    const auto d = h_.matrixLLT().diagonal();
    if (!d.allFinite() || !(d.minCoeff() > 1e-6 * d.maxCoeff())) return false;
    mass_ = 1.0 / inv_mass;
    inertia_ = inv_inertia.inverse();
    if (!inertia_.allFinite()) return false;
    count_ = count;
    return true;
}

Eigen::Matrix<double, 6, 1> SupportBlock::solveH(const Eigen::Matrix<double, 6, 1>& x) const {
    return scale_.cwiseProduct(h_.solve(scale_.cwiseProduct(x)));
}

void SupportBlock::solve(const SupportRow* rows, const double* e, Vec3& dv, Vec3& dw, double* p) const {
    Eigen::Matrix<double, 6, 1> we = Eigen::Matrix<double, 6, 1>::Zero();
    for (int i = 0; i < count_; ++i) {
        we.head<3>() += e[i] * rows[i].linear;
        we.tail<3>() += e[i] * rows[i].angular;
    }
    const Eigen::Matrix<double, 6, 1> du = solveH(we);
    dv = du.head<3>();
    dw = du.tail<3>();
    Eigen::Matrix<double, 6, 1> momentum;
    momentum << mass_ * dv, inertia_ * dw;
    const Eigen::Matrix<double, 6, 1> z = solveH(momentum);
    for (int i = 0; i < count_; ++i) p[i] = rows[i].linear.dot(z.head<3>()) + rows[i].angular.dot(z.tail<3>());
}

}  // namespace vroc::native
