#pragma once

namespace m350::ui {

// Drops the one note Qt's offscreen platform prints each time a window's minimum size changes
// ("This plugin does not support propagateSizeHints()"): the panel's minimum follows the page
// shown, so a headless replay printed it once per page switch (a million lines on stderr for a
// million-action replay, and a write to stderr each). Every other message passes on unchanged.
void installQuietOffscreen();

} // namespace m350::ui
