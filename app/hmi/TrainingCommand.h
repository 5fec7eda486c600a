#pragma once

#include "app/hmi/HmiOptions.h"

class QApplication;

namespace m350::ui {
class Language;
}

namespace m350::hmi {

// m350-hmi --training: the training's start page on the desktop; headless (--screenshot, --state)
// with --exercise DIR --replay ATTEMPT.jsonl it starts that exercise, plays the attempt through
// the training's panel (its faults injected as the grader does) and hands in when the attempt
// does, for the README's screenshots and the tests that compare the panel's verdict with the
// headless grader's.
int trainingCommand(QApplication& app, const HmiOptions& options, ui::Language& language);

} // namespace m350::hmi
