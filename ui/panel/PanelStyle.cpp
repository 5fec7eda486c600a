#include "ui/panel/PanelStyle.h"

#include <QFile>

namespace m350::ui {

QString panelStyleSheet() {
    QFile style(QStringLiteral(":/panel/panel.qss"));
    return style.open(QIODevice::ReadOnly) ? QString::fromUtf8(style.readAll()) : QString();
}

} // namespace m350::ui
