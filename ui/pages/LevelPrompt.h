#pragma once

#include "core/params/ParameterPages.h"

#include <QCoreApplication>

#include <functional>

namespace m350::ui {

class PanelContext;

// The panel's questions about user levels, shared by the Param and System pages.
class LevelPrompt {
    Q_DECLARE_TR_FUNCTIONS(m350::ui::LevelPrompt)

public:
    using Level = params::UserLevel;
    // 请输入[操作员]及以上密码切换用户权限: then the level opens (`opened` runs) or 解锁密码输入错误!.
    static void askPassword(const PanelContext& context, Level level, std::function<void()> opened = {});
    // Which level (0 访客 .. 3 超级管理), then its password; 访客 needs none.
    static void askLevel(const PanelContext& context);
    // 密码设置: 请输入新密码: and 请再次输入新密码:, for the current level.
    static void askNewPassword(const PanelContext& context);
    // 权限不足!: when the current level is below `needed`, says so, asks the password of `needed`
    // and returns false (`opened` runs once it opens); true at once when the level suffices.
    static bool require(const PanelContext& context, Level needed, std::function<void()> opened);
};

} // namespace m350::ui
