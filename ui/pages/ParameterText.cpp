#include "ui/pages/ParameterText.h"

#include "ui/i18n/PanelText.h"

#include <QStringList>

namespace m350::ui {

QString ParameterText::localName(const std::string& zh, const std::string& en, bool chinese) {
    return QString::fromStdString(chinese && !zh.empty() ? zh : en);
}
QString ParameterText::localName(const std::string& zh, const std::string& en) { return localName(zh, en, PanelText::chinese()); }

QString ParameterText::groupTitle(int group) {
    switch (group) {
    case 1: return tr("Machine", "msg 64");
    case 2: return tr("Manual", "msg 65");
    case 3: return tr("Process", "msg 66");
    case 4: return tr("Coordinate", "msg 67");
    case 5: return tr("Spindle", "msg 68");
    case 6: return tr("IO", "msg 69");
    case 7: return tr("Home", "msg 70");
    case 8: return tr("Probe", "msg 71");
    case 9: return tr("Hard Limit", "msg 72");
    case 10: return tr("Software limit", "msg 73");
    case 11: return tr("MPG", "msg 74");
    case 12: return tr("External", "msg 75");
    case 13: return tr("Backlash", "msg 76");
    case 14: return tr("Tools", "msg 77");
    case 15: return tr("System", "msg 78");
    default: break;
    }
    if (group == 16) {
        return tr("Input ports");
    }
    if (group == 17) {
        return tr("Output ports");
    }
    return tr("Not on the firmware's pages");
}

QString ParameterText::value(const params::ParameterInfo& info, double value) {
    if (info.type == params::ParameterInfo::Type::Select) {
        for (const params::ParameterOption& option : info.options) {
            if (option.value == value) {
                return QStringLiteral("%1 %2").arg(value).arg(localName(option.zh, option.en));
            }
        }
    }
    return info.type == params::ParameterInfo::Type::Real ? QString::number(value, 'f', 3) : QString::number(value);
}

QString ParameterText::range(const params::ParameterInfo& info) {
    if (info.type != params::ParameterInfo::Type::Select) {
        return QStringLiteral("%1 ~ %2").arg(info.min).arg(info.max);
    }
    QStringList options;
    for (const params::ParameterOption& option : info.options) {
        options << QStringLiteral("%1 = %2").arg(option.value).arg(localName(option.zh, option.en));
    }
    return QStringLiteral("\n  ") + options.join(QStringLiteral("\n  "));
}

} // namespace m350::ui
