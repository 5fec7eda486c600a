#include "ui/pages/LevelPrompt.h"

#include "ui/pages/PanelContext.h"
#include "ui/session/UserAccess.h"

namespace m350::ui {

namespace {

QString passwordQuestion(params::UserLevel level) {
    switch (level) {
    case params::UserLevel::Super:
        return LevelPrompt::tr("Pls input super admi or hight user's rights:", "msg 925");
    case params::UserLevel::Admin: return LevelPrompt::tr("Pls input admi or hight user's rights:", "msg 924");
    default: return LevelPrompt::tr("Pls input operator or hight user's rights:", "msg 923");
    }
}

} // namespace

void LevelPrompt::askPassword(const PanelContext& context, Level level, std::function<void()> opened) {
    context.askSecret(passwordQuestion(level), [&context, level, opened](std::optional<QString> password) {
        if (!password) {
            return;
        }
        if (!context.session().login(level, *password)) {
            context.notify(tr("Incorrect password!", "msg 905"));
            return;
        }
        context.notify(tr("User level: %1").arg(UserAccess::levelName(context.session().userLevel())));
        if (opened) {
            opened();
        }
    });
}

void LevelPrompt::askLevel(const PanelContext& context) {
    QString question = tr("Change user level (0 %1, 1 %2, 2 %3, 3 %4):")
                           .arg(UserAccess::levelName(Level::Guest), UserAccess::levelName(Level::Operator),
                                UserAccess::levelName(Level::Admin), UserAccess::levelName(Level::Super));
    context.askText(question, {}, [&context](std::optional<QString> text) {
        if (!text) {
            return;
        }
        bool ok = false;
        int level = text->trimmed().toInt(&ok);
        if (!ok || level < 0 || level > 3) {
            context.notify(tr("Enter 0, 1, 2 or 3"));
        } else if (level == 0) {
            context.session().login(Level::Guest, {});
            context.notify(tr("User level: %1").arg(UserAccess::levelName(Level::Guest)));
        } else {
            askPassword(context, static_cast<Level>(level));
        }
    });
}

void LevelPrompt::askNewPassword(const PanelContext& context) {
    if (context.session().userLevel() == Level::Guest) {
        context.notify(tr("Rights is limited,pls shift user's rights:", "msg 934"));
        askLevel(context);
        return;
    }
    context.askSecret(tr("Pls input new password:", "msg 922"), [&context](std::optional<QString> first) {
        if (!first) {
            return;
        }
        if (first->size() < UserAccess::kMinimumLength) {
            context.notify(tr("The No. of characters < 6,pls input again!", "msg 918"));
            return;
        }
        context.askSecret(tr("Pls input password again:", "msg 921"),
                        [&context, first = *first](std::optional<QString> second) {
                            if (!second) {
                                return;
                            }
                            if (*second != first) {
                                context.notify(tr("Two entries are not the same,pls input again!", "msg 919"));
                                return;
                            }
                            auto error = context.session().changePassword(first);
                            context.notify(error ? *error : tr("Successfully modified!", "msg 920"));
                        });
    });
}

bool LevelPrompt::require(const PanelContext& context, Level needed, std::function<void()> opened) {
    if (context.session().userLevel() >= needed) {
        return true;
    }
    context.notify(tr("Rights is limited,pls shift user's rights:", "msg 934"));
    askPassword(context, needed, std::move(opened));
    return false;
}

} // namespace m350::ui
