#pragma once

#include "app/hmi/HmiOptions.h"

namespace m350::ui {
class Language;
}

namespace m350::hmi {

// m350-hmi --exercise DIR --attempt A.jsonl [--verdict OUT.json]: grades the attempt offscreen,
// prints one line per check and the result, writes the verdict. Exit 0 passed, 1 failed, 2 when
// it cannot be graded (a bad exercise or attempt, an output refused).
int gradeCommand(const HmiOptions& options, ui::Language& language);

// m350-hmi --class-report FOLDER [--report-csv F] [--report-html F]: every attempt graded, the
// class's table printed and written. Exit 0 when every attempt could be graded, 2 otherwise.
int classReportCommand(const HmiOptions& options, ui::Language& language);

} // namespace m350::hmi
