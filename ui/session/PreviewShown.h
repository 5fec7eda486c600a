#pragma once

#include <QString>

#include <memory>

namespace m350::preview {
struct Preview;
}

namespace m350::ui {

// A program's preview as the snapshots carry it: the machine view draws `preview` (shared, never
// changed) while `file` is the program it shows; `building` while a newer one is being made.
struct PreviewShown {
    QString file;
    std::shared_ptr<const preview::Preview> preview;
    bool building = false;
};

} // namespace m350::ui
