#include "core/files/OutputGuard.h"

#include <sys/stat.h>

namespace m350::files {

namespace fs = std::filesystem;

namespace {

// Where a path leads once every link and `..` of it that exists is followed; the parts not made
// yet stay as written.
fs::path resolvedPath(const fs::path& path) {
    std::error_code ec;
    const fs::path absolute = fs::absolute(path, ec);
    if (ec) {
        return path.lexically_normal();
    }
    const fs::path resolved = fs::weakly_canonical(absolute, ec);
    return ec ? absolute.lexically_normal() : resolved;
}

bool isInside(const fs::path& file, const fs::path& folder) {
    const fs::path relative = file.lexically_relative(folder);
    return !relative.empty() && relative != "." && *relative.begin() != "..";
}

fs::path parentOf(const fs::path& output) { return output.has_parent_path() ? output.parent_path() : fs::path("."); }

} // namespace

std::optional<GuardHit> outputOverGuarded(const fs::path& output, const std::vector<GuardedPath>& guarded) {
    const fs::path target = resolvedPath(output);
    std::error_code ec;
    const bool regular = fs::is_regular_file(output, ec);
    for (const GuardedPath& g : guarded) {
        if (g.folder ? isInside(target, resolvedPath(g.path)) : regular && fs::equivalent(output, g.path, ec)) {
            return GuardHit{g, g.folder};
        }
    }
    return std::nullopt;
}

std::optional<Message> refusedOutput(const std::string& option, const fs::path& output,
                                     const std::vector<GuardedPath>& guarded) {
    auto hit = outputOverGuarded(output, guarded);
    if (!hit) {
        return std::nullopt;
    }
    return message(hit->inside ? "output_inside_guarded" : "output_is_guarded",
                   {option, output.string(), hit->guarded.what, hit->guarded.path.string()});
}

std::optional<Unwritable> unwritableOutput(const fs::path& output) {
    struct stat existing {};
    if (::stat(output.c_str(), &existing) == 0) {
        if (S_ISDIR(existing.st_mode)) return Unwritable::Folder;
        if (S_ISSOCK(existing.st_mode)) return Unwritable::Socket;
        if (S_ISBLK(existing.st_mode)) return Unwritable::BlockDevice;
        return std::nullopt;
    }
    struct stat folder {};
    if (::stat(parentOf(output).c_str(), &folder) != 0) return Unwritable::NoFolder;
    if (!S_ISDIR(folder.st_mode)) return Unwritable::ParentNotFolder;
    return std::nullopt;
}

Message describeUnwritable(const std::string& option, const fs::path& output, Unwritable why) {
    switch (why) {
    case Unwritable::Folder: return message("output_is_folder", {option, output.string()});
    case Unwritable::Socket: return message("output_is_socket", {option, output.string()});
    case Unwritable::BlockDevice: return message("output_is_disk", {option, output.string()});
    case Unwritable::NoFolder: return message("output_no_folder", {option, output.string(), parentOf(output).string()});
    case Unwritable::ParentNotFolder:
        break;
    }
    return message("output_parent_not_folder", {option, output.string(), parentOf(output).string()});
}

} // namespace m350::files
