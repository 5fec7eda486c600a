#pragma once

#include <string>
#include <vector>

namespace m350::testing {

// What a finished child process left behind: its stdout and stderr kept apart, and its exit status
// (128 + signal number when a signal ended it, as a shell reports it).
struct ProcessResult {
    std::string out;
    std::string err;
    int exitStatus = -1;
};

// Runs `program args...` in `workingDirectory` (the current one when empty) and waits for it.
// Both pipes are drained together, so a child writing a lot to either never blocks.
ProcessResult runProcess(const std::string& program, const std::vector<std::string>& args,
                         const std::string& workingDirectory = {});

// A folder or file name as a GoogleTest case name: every character that is not a letter or digit
// becomes '_' (`m350-t-code` -> `m350_t_code`).
std::string testNameFor(const std::string& name);

} // namespace m350::testing
