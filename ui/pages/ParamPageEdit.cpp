// What the Param page's keys change: a parameter or a #50-#499 variable through the prompt, the
// search by number, and 参数备份 / 参数恢复.
#include "ui/pages/ParamPage.h"
#include "ui/pages/ParameterText.h"

#include "core/config/MachineFolder.h"
#include "core/params/ParameterBackup.h"
#include "ui/i18n/Language.h"
#include "ui/i18n/PanelText.h"
#include "ui/pages/LevelPrompt.h"
#include "ui/pages/PanelContext.h"

#include <QDir>
#include <QFileInfo>

#include <cmath>
#include <variant>

namespace m350::ui {

namespace {

// Who may set a #50-#499 variable by hand: a program may anyway, so the lowest signed-in level.
constexpr params::UserLevel kVariableLevel = params::UserLevel::Operator;

QString backupPath(const PanelContext& context) {
    return QString::fromStdString(context.folderFiles().pathOf(config::FolderFile::ParamsBackup).string());
}

} // namespace

void ParamPage::edit() {
    int number = selectedNumber();
    if (number < 0) {
        return;
    }
    if (variables_) {
        editVariable(number);
    } else {
        editParameter(number);
    }
}

void ParamPage::editParameter(int number) {
    const params::ParameterInfo& info = *catalogue_->find(number);
    if (!LevelPrompt::require(context(), params::ParameterPages::requiredLevel(info.group),
                              [this, number] { editParameter(number); })) {
        return;
    }
    QString question = QStringLiteral("[%1] %2").arg(number).arg(
        QString::fromStdString(PanelText::chinese() ? info.nameZh : info.nameEn));
    if (info.type == params::ParameterInfo::Type::Select) {
        question += QStringLiteral(" (") + ParameterText::range(info).trimmed().replace(QStringLiteral("\n  "), QStringLiteral(", ")) +
                    QStringLiteral(")");
    }
    context().askText(question + QStringLiteral(":"), {}, [this, number](std::optional<QString> text) {
        if (!text) {
            return;
        }
        bool ok = false;
        double value = text->trimmed().toDouble(&ok);
        if (!ok || catalogue_->validate(number, value)) {
            context().notify(tr("[%d]The data entered is illegal!", "msg 802").replace(QStringLiteral("%d"), QString::number(number)));
            return;
        }
        context().session().setParameter(number, value);
        context().notify({});
    });
}

void ParamPage::editVariable(int number) {
    if (!LevelPrompt::require(context(), kVariableLevel, [this, number] { editVariable(number); })) {
        return;
    }
    auto s = context().snapshot();
    int index = number - 50;
    QString current = s && index < s->userVariables.size() && !std::isnan(s->userVariables[index])
                          ? QString::number(s->userVariables[index])
                          : QString();
    context().askText(QStringLiteral("#%1 =").arg(number), current, [this, number](std::optional<QString> text) {
        if (!text) {
            return;
        }
        bool ok = false;
        double value = text->trimmed().toDouble(&ok);
        if (!ok || !std::isfinite(value)) {
            context().notify(tr("Variable #%1: not a number").arg(number));
            return;
        }
        context().session().setVariable(number, value);
        context().notify({});
    });
}

void ParamPage::search() {
    context().askText(tr("Input searching parameter No. :", "msg 935"), {}, [this](std::optional<QString> text) {
        if (!text) {
            return;
        }
        bool ok = false;
        int number = text->trimmed().toInt(&ok);
        if (!ok || !select(number)) {
            context().notify(tr("Parameter %1 is not on the parameter pages").arg(text->trimmed()));
            return;
        }
        context().notify({});
    });
}

void ParamPage::backup() {
    auto s = context().snapshot();
    if (!s) {
        return;
    }
    QString path = backupPath(context());
    std::string text = params::formatParameterBackup(s->status.parameters, *catalogue_, s->machineName.toStdString());
    if (auto error = context().folderFiles().write(config::FolderFile::ParamsBackup, text)) {
        context().notify(tr("File save failed!", "msg 907") + QStringLiteral(" ") + QString::fromStdString(error->in(Language::messageLanguage())));
        return;
    }
    context().notify(tr("Parameters backed up to %1").arg(QFileInfo(path).fileName()));
}

void ParamPage::restore() {
    if (!LevelPrompt::require(context(), params::UserLevel::Admin, [this] { restore(); })) {
        return;
    }
    QString path = backupPath(context());
    if (!QFileInfo::exists(path)) {
        context().notify(tr("No backup: %1 does not exist (Param Backup writes it)").arg(QFileInfo(path).fileName()));
        return;
    }
    context().ask(tr("Restore every parameter from %1?").arg(QFileInfo(path).fileName()), [this, path](bool yes) {
        if (!yes) {
            return;
        }
        auto read = params::readParameterBackup(path.toStdString(), *catalogue_);
        if (auto* error = std::get_if<Message>(&read)) {
            context().notify(tr("Parameter restore refused, nothing changed: %1").arg(QString::fromStdString(error->in(Language::messageLanguage()))));
            return;
        }
        const params::ParameterRestore& restore = std::get<params::ParameterRestore>(read);
        auto s = context().snapshot();
        std::map<int, double> changed;
        for (auto [number, value] : restore.values) {
            if (!s || s->status.parameters.get(number) != value) {
                changed[number] = value;
            }
        }
        context().session().setParameters(changed);
        QString done = tr("Parameters restored from %1: %2 changed").arg(QFileInfo(path).fileName()).arg(changed.size());
        if (!restore.outOfRange.empty()) {
            done += tr("; %1 outside their ranges kept as saved").arg(restore.outOfRange.size());
        }
        context().notify(done);
    });
}

} // namespace m350::ui
