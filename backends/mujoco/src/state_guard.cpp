// SPDX-License-Identifier: MIT
#include "state_guard.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "vroc/core/backend_vocabulary.h"

namespace vroc::mujoco {
namespace {

// MuJoCo's own test for a bad number (mju_isBad): NaN, or beyond +-mjMAXVAL (Inf included).
bool bad(double x) { return !(std::abs(x) <= mjMAXVAL); }

std::vector<double> copy(const double* x, int n) { return std::vector<double>(x, x + n); }

}  // namespace

StateGuard::StateGuard(const mjModel& m, const mjData& d, std::vector<BodySlots> slots)
    : slots_(std::move(slots)),
      good_qpos_(copy(d.qpos, m.nq)),
      good_qvel_(copy(d.qvel, m.nv)),
      good_warm_(copy(d.qacc_warmstart, m.nv)),
      blamed_(slots_.size(), 0) {}

void StateGuard::beforeStep(mjData& d) {
    pre_qpos_.assign(d.qpos, d.qpos + good_qpos_.size());
    pre_qvel_.assign(d.qvel, d.qvel + good_qvel_.size());
    pre_warm_.assign(d.qacc_warmstart, d.qacc_warmstart + good_warm_.size());
    for (mjWarningStat& w : d.warning) w = mjWarningStat{0, 0};
}

bool StateGuard::bodyIsBad(const std::vector<double>& qpos, const std::vector<double>& qvel, const BodySlots& s) const {
    if (s.qpos < 0) return false;
    for (int k = 0; k < 7; ++k)
        if (bad(qpos[static_cast<std::size_t>(s.qpos + k)])) return true;
    for (int k = 0; k < 6; ++k)
        if (bad(qvel[static_cast<std::size_t>(s.dof + k)])) return true;
    return false;
}

void StateGuard::blameIndex(int index, bool is_dof) {
    for (std::size_t i = 0; i < slots_.size(); ++i) {
        const int first = is_dof ? slots_[i].dof : slots_[i].qpos;
        const int count = is_dof ? 6 : 7;
        if (first >= 0 && index >= first && index < first + count) blamed_[i] = 1;
    }
}

bool StateGuard::afterStep(const mjModel& m, const mjData& d, bool threw) {
    threw_ = threw;
    if (threw) ++errors_;
    contact_full_ += static_cast<std::uint64_t>(d.warning[mjWARN_CONTACTFULL].number);
    constraint_full_ += static_cast<std::uint64_t>(d.warning[mjWARN_CNSTRFULL].number);
    inertia_ += static_cast<std::uint64_t>(d.warning[mjWARN_INERTIA].number);
    const mjWarningStat& wpos = d.warning[mjWARN_BADQPOS];
    const mjWarningStat& wvel = d.warning[mjWARN_BADQVEL];
    const mjWarningStat& wacc = d.warning[mjWARN_BADQACC];
    bad_qpos_ += static_cast<std::uint64_t>(wpos.number);
    bad_qvel_ += static_cast<std::uint64_t>(wvel.number);
    bad_qacc_ += static_cast<std::uint64_t>(wacc.number);

    std::fill(blamed_.begin(), blamed_.end(), 0);
    bool trouble = threw || wpos.number > 0 || wvel.number > 0 || wacc.number > 0;
    if (wpos.number > 0) blameIndex(wpos.lastinfo, false);
    if (wvel.number > 0) blameIndex(wvel.lastinfo, true);
    if (wacc.number > 0) blameIndex(wacc.lastinfo, true);
    const std::vector<double> qpos = copy(d.qpos, m.nq), qvel = copy(d.qvel, m.nv);
    for (std::size_t i = 0; i < slots_.size(); ++i) {
        if (bodyIsBad(pre_qpos_, pre_qvel_, slots_[i]) || bodyIsBad(qpos, qvel, slots_[i])) {
            blamed_[i] = 1;
            trouble = true;
        }
    }
    if (trouble) return false;
    good_qpos_ = qpos;
    good_qvel_ = qvel;
    good_warm_.assign(d.qacc_warmstart, d.qacc_warmstart + m.nv);
    return true;
}

int StateGuard::recover(const mjModel& m, mjData& d, bool at_rest) {
    // An error may leave MuJoCo's scratch stack marked; a reset clears every derived quantity.
    if (threw_) mj_resetData(&m, &d);
    std::vector<double> qpos = pre_qpos_, qvel = pre_qvel_, warm = pre_warm_;
    int put_back = 0;
    for (std::size_t i = 0; i < slots_.size(); ++i) {
        if (!blamed_[i] || slots_[i].qpos < 0) continue;
        const auto p = static_cast<std::size_t>(slots_[i].qpos), v = static_cast<std::size_t>(slots_[i].dof);
        for (std::size_t k = 0; k < 7; ++k) qpos[p + k] = good_qpos_[p + k];
        for (std::size_t k = 0; k < 6; ++k) {
            qvel[v + k] = at_rest ? 0.0 : good_qvel_[v + k];
            warm[v + k] = good_warm_[v + k];
        }
        ++put_back;
    }
    std::copy(qpos.begin(), qpos.end(), d.qpos);
    std::copy(qvel.begin(), qvel.end(), d.qvel);
    std::copy(warm.begin(), warm.end(), d.qacc_warmstart);
    for (mjWarningStat& w : d.warning) w = mjWarningStat{0, 0};
    return put_back;
}

void StateGuard::restoreStart(mjData& d) const {
    std::copy(pre_qpos_.begin(), pre_qpos_.end(), d.qpos);
    std::copy(pre_qvel_.begin(), pre_qvel_.end(), d.qvel);
    std::copy(pre_warm_.begin(), pre_warm_.end(), d.qacc_warmstart);
    for (mjWarningStat& w : d.warning) w = mjWarningStat{0, 0};
}

WarningCounts StateGuard::counts() const {
    return {{"mujoco.bad_qpos", bad_qpos_},
            {"mujoco.bad_qvel", bad_qvel_},
            {"mujoco.bad_qacc", bad_qacc_},
            {"mujoco.contact_full", contact_full_},
            {"mujoco.constraint_full", constraint_full_},
            {"mujoco.inertia", inertia_},
            {"mujoco.error", errors_},
            // The shared name for both kinds of drop: the harness marks such a run not valid.
            {vocabulary::kContactsDropped, contact_full_ + constraint_full_}};
}

}  // namespace vroc::mujoco
