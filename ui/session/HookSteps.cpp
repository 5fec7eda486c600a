#include "ui/session/HookSteps.h"

namespace m350::ui {

MachineSession::HookStep goToWorkZeroStep(const QVector<int>& axes) {
    const char* const names = "XYZAB";
    QStringList lines{QStringLiteral("G90 G00 Z#569")}; // param 69: the Z safe height
    QString over = QStringLiteral("G00");
    for (int axis : axes) {
        if (axis != 2) {
            over += QStringLiteral(" %1 0").arg(QChar(names[axis]));
        }
    }
    lines << over << QStringLiteral("G00 Z0");
    return {config::Hook::GoToWorkZero, {}, lines};
}

std::optional<MachineSession::HookStep> mCodeKeyStep(int code) {
    auto hook = config::mCodeKeyHook(code);
    if (!hook) {
        return std::nullopt;
    }
    return MachineSession::HookStep{*hook, {}, {QStringLiteral("M%1").arg(code)}};
}

} // namespace m350::ui
