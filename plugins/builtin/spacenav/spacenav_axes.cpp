// SPDX-License-Identifier: MIT
#include "spacenav_axes.h"

#include <algorithm>

namespace vroc::plugins::spacenav {

MouseAxes spacenavToVrocAxes(const std::array<int, 6>& c, double full_scale) {
    const auto n = [full_scale](int count) { return std::clamp(count / full_scale, -1.0, 1.0); };
    return {n(c[2]), -n(c[0]), n(c[1]), n(c[5]), -n(c[3]), n(c[4])};
}

}  // namespace vroc::plugins::spacenav
