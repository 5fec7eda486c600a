#include "core/devices/MultiHead.h"

#include "core/devices/DeviceText.h"

#include <algorithm>

namespace m350::devices {

MultiHead::MultiHead(int heads, double safeZ, double tolerance, int headDown)
    : down_(static_cast<std::size_t>(std::clamp(heads, 1, 4)), false), safeZ_(safeZ), tolerance_(tolerance) {
    if (headDown >= 1 && headDown <= pocketCount()) {
        down_[static_cast<std::size_t>(headDown - 1)] = true;
    }
}

int MultiHead::spindleTool() const {
    if (std::count(down_.begin(), down_.end(), true) != 1) {
        return 0;
    }
    return static_cast<int>(std::find(down_.begin(), down_.end(), true) - down_.begin()) + 1;
}

std::optional<Message> MultiHead::move(const Eigen::Vector3d& from, const Eigen::Vector3d& to, bool, bool,
                                           double) {
    if (std::count(down_.begin(), down_.end(), true) < 2 || (to - from).norm() < 1e-6) {
        return std::nullopt;
    }
    std::string heads;
    for (std::size_t k = 0; k < down_.size(); ++k) {
        if (down_[k]) {
            heads += (heads.empty() ? "" : ", ") + std::to_string(k + 1); // numbers only: a message argument
        }
    }
    return message("heads_down_together", {heads, text::position(from), text::position(to)});
}

std::optional<Message> MultiHead::cylinder(int head, bool down, const Eigen::Vector3d& nose) {
    if (head < 1 || head > pocketCount()) {
        return std::nullopt;
    }
    auto state = down_[static_cast<std::size_t>(head - 1)]; // a reference into the bits
    if (state == down) {
        return std::nullopt;
    }
    state = down;
    if (down && nose.z() < safeZ_ - tolerance_) {
        return message("head_down_low", {std::to_string(head), text::position(nose), text::millimetres(safeZ_)});
    }
    return std::nullopt;
}

} // namespace m350::devices
