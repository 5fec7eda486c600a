#pragma once

#include "app/hmi/HmiOptions.h"

class QApplication;

namespace m350::ui {
class Language;
}

namespace m350::hmi {

// m350-hmi --review ATTEMPT.jsonl --exercise DIR: a trainer's review of a recorded attempt on the
// exercise's machine, with the review bar (1x-50x, pause, one block at a time). Headless
// (--screenshot, --state) it plays the attempt to --review-until T (default: to its end) at once
// and renders that moment. Exit 2 when the review cannot open (a bad exercise or attempt).
int reviewCommand(QApplication& app, const HmiOptions& options, ui::Language& language);

} // namespace m350::hmi
