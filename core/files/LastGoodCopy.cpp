#include "core/files/LastGoodCopy.h"

#include <fstream>
#include <iterator>

namespace m350::files {

namespace fs = std::filesystem;

namespace {

std::optional<std::string> readWhole(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) {
        return std::nullopt;
    }
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) {
        return std::nullopt;
    }
    return bytes;
}

} // namespace

fs::path lastGoodPath(const fs::path& file) {
    fs::path copy = file;
    copy += ".last-good";
    return copy;
}

std::optional<Message> saveKeepingLastGood(const fs::path& file, std::string_view content,
                                               const AtomicWriteHooks& hooks) {
    if (auto error = writeFileAtomically(file, content, hooks)) {
        return error;
    }
    return writeFileAtomically(lastGoodPath(file), content);
}

void refreshLastGood(const fs::path& file) {
    const fs::path copy = lastGoodPath(file);
    std::error_code ec;
    if (!fs::is_regular_file(copy, ec)) {
        return;
    }
    std::optional<std::string> now = readWhole(file);
    if (now && now != readWhole(copy)) {
        (void)writeFileAtomically(copy, *now); // best effort: the folder loaded; a stale copy is still a good one
    }
}

std::string lastGoodNote(const fs::path& file) {
    std::error_code ec;
    const fs::path copy = lastGoodPath(file);
    return fs::is_regular_file(copy, ec) ? " (its last good copy: " + copy.string() + ")" : std::string();
}

} // namespace m350::files
