#include "ui/panel/QuietOffscreen.h"

#include <QLatin1StringView>
#include <QtGlobal>

namespace m350::ui {

namespace {

QtMessageHandler passedOn = nullptr;

void dropSizeHintsNote(QtMsgType type, const QMessageLogContext& context, const QString& text) {
    if (type == QtWarningMsg && text == QLatin1StringView("This plugin does not support propagateSizeHints()")) {
        return;
    }
    passedOn(type, context, text);
}

} // namespace

void installQuietOffscreen() {
    if (!passedOn) {
        passedOn = qInstallMessageHandler(dropSizeHintsNote);
    }
}

} // namespace m350::ui
