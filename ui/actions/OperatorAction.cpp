#include "ui/actions/OperatorAction.h"

#include "ui/actions/PanelKey.h"
#include "ui/pages/PageTable.h"

#include <QJsonValue>
#include <QStringList>

#include <QCoreApplication>

namespace m350::ui {

namespace {

const char* kindKey(OperatorAction::Kind kind) {
    switch (kind) {
    case OperatorAction::Kind::Key: return "key";
    case OperatorAction::Kind::KeyDown: return "key_down";
    case OperatorAction::Kind::KeyUp: return "key_up";
    case OperatorAction::Kind::Softkey: return "softkey";
    case OperatorAction::Kind::Text: return "text";
    case OperatorAction::Kind::Wheel: return "wheel";
    case OperatorAction::Kind::Page: return "page";
    case OperatorAction::Kind::Force: return "force";
    case OperatorAction::Kind::Language: return "lang";
    case OperatorAction::Kind::Load: return "load";
    case OperatorAction::Kind::Wait: return "";
    }
    return "";
}

int axisIndex(const QString& name) {
    static const QString axes = QStringLiteral("XYZAB");
    return name.size() == 1 ? static_cast<int>(axes.indexOf(name.at(0).toUpper())) : -1;
}

} // namespace

QJsonObject OperatorAction::toJson() const {
    QJsonObject out;
    out["t"] = t;
    switch (kind) {
    case Kind::Key:
    case Kind::KeyDown:
    case Kind::KeyUp:
    case Kind::Page:
    case Kind::Language:
    case Kind::Load: out[kindKey(kind)] = name; break;
    case Kind::Softkey: out["softkey"] = softkey; break;
    case Kind::Text: out["text"] = text; break;
    case Kind::Wheel:
        out["wheel"] = QJsonObject{{"axis", QString(QStringLiteral("XYZAB").at(wheel.axis))},
                                   {"step", wheel.step},
                                   {"detents", wheel.detents},
                                   {"seconds", wheel.seconds}};
        break;
    case Kind::Force: {
        QJsonObject f{{"input", force.input}};
        if (force.fault == QLatin1String("stuck")) {
            f["level"] = force.level;
        } else {
            f["fault"] = force.fault;
            if (force.fault != QLatin1String("none")) {
                f["seconds"] = force.seconds;
            }
            if (force.fault == QLatin1String("pressed")) {
                f["level"] = force.level;
            }
        }
        out["force"] = f;
        break;
    }
    case Kind::Wait: break;
    }
    return out;
}

std::optional<OperatorAction> OperatorAction::fromJson(const QJsonObject& object, QString* error) {
    auto fail = [error](const QString& why) -> std::optional<OperatorAction> {
        if (error) {
            *error = why;
        }
        return std::nullopt;
    };
    OperatorAction a;
    if (!object.contains(QLatin1String("t")) || !object.value(QLatin1String("t")).isDouble() || object.value(QLatin1String("t")).toDouble() < 0.0) {
        return fail(QCoreApplication::translate("m350::ui::OperatorAction", "\"t\" (virtual time in seconds, >= 0) is missing or not a number"));
    }
    a.t = object.value(QLatin1String("t")).toDouble();
    const auto kinds = object.size() - 1; // besides "t" (a replay reads a million of these: no list of keys)
    if (kinds > 1) {
        return fail(QCoreApplication::translate("m350::ui::OperatorAction", "one action per line: found %1 besides \"t\"").arg(kinds));
    }
    for (Kind kind : {Kind::Key, Kind::KeyDown, Kind::KeyUp}) {
        if (object.contains(QLatin1String(kindKey(kind)))) {
            a.kind = kind;
            a.name = object.value(QLatin1String(kindKey(kind))).toString();
            if (!PanelKey::named(a.name)) {
                return fail(QCoreApplication::translate("m350::ui::OperatorAction", "unknown key \"%1\"").arg(a.name));
            }
            return a;
        }
    }
    if (object.contains(QLatin1String("softkey"))) {
        a.kind = Kind::Softkey;
        a.softkey = object.value(QLatin1String("softkey")).toInt();
        if (a.softkey < 1 || a.softkey > 12) {
            return fail(QCoreApplication::translate("m350::ui::OperatorAction", "softkey must be 1-6 (F1-F6) or 7-12 (second row)"));
        }
        return a;
    }
    if (object.contains(QLatin1String("text"))) {
        a.kind = Kind::Text;
        a.text = object.value(QLatin1String("text")).toString();
        return a;
    }
    if (object.contains(QLatin1String("page"))) {
        a.kind = Kind::Page;
        a.name = object.value(QLatin1String("page")).toString();
        if (!PageTable::ids().contains(a.name)) {
            return fail(QCoreApplication::translate("m350::ui::OperatorAction", "unknown page \"%1\" (one of: %2)").arg(a.name, PageTable::ids().join(", ")));
        }
        return a;
    }
    if (object.contains(QLatin1String("lang"))) {
        a.kind = Kind::Language;
        a.name = object.value(QLatin1String("lang")).toString();
        if (a.name != QLatin1String("zh_CN") && a.name != QLatin1String("en")) {
            return fail(QCoreApplication::translate("m350::ui::OperatorAction", "lang must be zh_CN or en"));
        }
        return a;
    }
    if (object.contains(QLatin1String("load"))) {
        a.kind = Kind::Load;
        a.name = object.value(QLatin1String("load")).toString();
        return a;
    }
    if (object.contains(QLatin1String("wheel"))) {
        QJsonObject w = object.value(QLatin1String("wheel")).toObject();
        a.kind = Kind::Wheel;
        a.wheel.axis = axisIndex(w.value(QLatin1String("axis")).toString());
        a.wheel.step = w.value(QLatin1String("step")).toInt(1);
        a.wheel.detents = w.value(QLatin1String("detents")).toInt();
        a.wheel.seconds = w.value(QLatin1String("seconds")).toDouble(0.0);
        if (a.wheel.axis < 0) {
            return fail(QCoreApplication::translate("m350::ui::OperatorAction", "wheel axis must be X, Y, Z, A or B"));
        }
        if (a.wheel.step != 1 && a.wheel.step != 10 && a.wheel.step != 100) {
            return fail(QCoreApplication::translate("m350::ui::OperatorAction", "wheel step must be 1, 10 or 100"));
        }
        if (!(a.wheel.seconds >= 0.0)) {
            return fail(QCoreApplication::translate("m350::ui::OperatorAction", "wheel seconds must be >= 0"));
        }
        return a;
    }
    if (object.contains(QLatin1String("force"))) {
        QJsonObject f = object.value(QLatin1String("force")).toObject();
        a.kind = Kind::Force;
        a.force.input = f.value(QLatin1String("input")).toInt();
        a.force.fault = f.value(QLatin1String("fault")).toString(QStringLiteral("stuck"));
        a.force.level = f.value(QLatin1String("level")).toInt();
        a.force.seconds = f.value(QLatin1String("seconds")).toDouble(0.0);
        if (a.force.input < 1 || a.force.input > 24) {
            return fail(QCoreApplication::translate("m350::ui::OperatorAction", "force input must be 1-24 (IN01-IN24)"));
        }
        static const QStringList faults{"stuck", "slow", "bouncing", "pressed", "none"};
        if (!faults.contains(a.force.fault)) {
            return fail(QCoreApplication::translate("m350::ui::OperatorAction", "force fault must be stuck, slow, bouncing, pressed or none"));
        }
        const bool levelled = a.force.fault == QLatin1String("stuck") || a.force.fault == QLatin1String("pressed");
        if (levelled && a.force.level != 0 && a.force.level != 1) {
            return fail(QCoreApplication::translate("m350::ui::OperatorAction", "force level must be 0 or 1"));
        }
        return a;
    }
    if (kinds == 0) {
        return a; // {"t": 8}: time passes
    }
    QStringList names = object.keys();
    names.removeAll(QStringLiteral("t"));
    return fail(QCoreApplication::translate("m350::ui::OperatorAction", "unknown action \"%1\" (one of: key, key_down, key_up, softkey, text, wheel, page, "
                               "force, lang, load)")
                    .arg(names.join(", ")));
}

} // namespace m350::ui
