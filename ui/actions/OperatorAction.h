#pragma once

#include <QJsonObject>
#include <QString>

#include <optional>

namespace m350::ui {

// One thing an operator does: a key, a softkey, typed text, a turn of the handwheel, a page
// change, a trainer's fault on an input, or nothing (time passing). Keyboard, mouse, tests and
// replays all produce these values and hand them to the one ActionDispatcher.
struct OperatorAction {
    enum class Kind { Key, KeyDown, KeyUp, Softkey, Text, Wheel, Page, Force, Language, Load, Wait };
    Kind kind = Kind::Wait;
    double t = 0.0;  // virtual time of the action, s (replay and record)
    QString name;    // key name (PanelKey: START, JOG_X+ ...), page id (PageTable), language, file
    int softkey = 0; // 1-6 the first row (F1-F6), 7-12 the second (Shift+F1-F6)
    QString text;
    struct Wheel {
        int axis = 0;       // 0..4 = X Y Z A B
        int step = 1;       // x1 x10 x100
        int detents = 0;    // signed: + clockwise
        double seconds = 0; // over how long they were turned
    } wheel;
    struct Force {
        int input = 0;
        QString fault = QStringLiteral("stuck"); // stuck, slow, bouncing, none
        int level = 0;
        double seconds = 0.0;
    } force;

    static OperatorAction key(const QString& name) { return make(Kind::Key, name); }
    static OperatorAction keyDown(const QString& name) { return make(Kind::KeyDown, name); }
    static OperatorAction keyUp(const QString& name) { return make(Kind::KeyUp, name); }
    static OperatorAction page(const QString& id) { return make(Kind::Page, id); }
    static OperatorAction softkeyPress(int number) {
        OperatorAction a = make(Kind::Softkey, {});
        a.softkey = number;
        return a;
    }
    static OperatorAction typed(const QString& text) {
        OperatorAction a = make(Kind::Text, {});
        a.text = text;
        return a;
    }
    static OperatorAction wheelTurn(int axis, int step, int detents, double seconds) {
        OperatorAction a = make(Kind::Wheel, {});
        a.wheel = {axis, step, detents, seconds};
        return a;
    }

    // The replay/record line format: {"t":0.4,"softkey":1}; see the README.
    QJsonObject toJson() const;
    static std::optional<OperatorAction> fromJson(const QJsonObject& object, QString* error);

private:
    static OperatorAction make(Kind kind, const QString& name) {
        OperatorAction a;
        a.kind = kind;
        a.name = name;
        return a;
    }
};

} // namespace m350::ui
