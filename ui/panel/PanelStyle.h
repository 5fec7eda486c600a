#pragma once

#include <QString>

namespace m350::ui {

// The panel's look (colours, fonts, key sizes: resources/panel.qss), as the application's style
// sheet; m350-hmi sets it, and tests that measure the window set it to measure what a user sees.
QString panelStyleSheet();

} // namespace m350::ui
