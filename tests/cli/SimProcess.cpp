#include "tests/cli/SimProcess.h"

#include <poll.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <stdexcept>
#include <system_error>

extern char** environ;

namespace m350::testing {

namespace {

[[noreturn]] void failWith(const char* what, int error) {
    throw std::system_error(error, std::generic_category(), what);
}

// A pipe whose ends close themselves.
class Pipe {
  public:
    Pipe() {
        if (::pipe(fds_.data()) != 0) {
            failWith("pipe", errno);
        }
    }
    ~Pipe() {
        closeRead();
        closeWrite();
    }
    Pipe(const Pipe&) = delete;
    Pipe& operator=(const Pipe&) = delete;

    int readEnd() const { return fds_[0]; }
    int writeEnd() const { return fds_[1]; }
    void closeRead() { closeEnd(0); }
    void closeWrite() { closeEnd(1); }

  private:
    void closeEnd(std::size_t i) {
        if (fds_[i] >= 0) {
            ::close(fds_[i]);
            fds_[i] = -1;
        }
    }
    std::array<int, 2> fds_{-1, -1};
};

class SpawnActions {
  public:
    SpawnActions() { posix_spawn_file_actions_init(&actions_); }
    ~SpawnActions() { posix_spawn_file_actions_destroy(&actions_); }
    SpawnActions(const SpawnActions&) = delete;
    SpawnActions& operator=(const SpawnActions&) = delete;
    posix_spawn_file_actions_t* get() { return &actions_; }

  private:
    posix_spawn_file_actions_t actions_{};
};

// Reads both pipes until the child has closed them.
void drain(Pipe& out, Pipe& err, ProcessResult& result) {
    std::array<pollfd, 2> fds{{{out.readEnd(), POLLIN, 0}, {err.readEnd(), POLLIN, 0}}};
    std::array<std::string*, 2> sinks{&result.out, &result.err};
    int open = 2;
    char buffer[8192];
    while (open > 0) {
        if (::poll(fds.data(), fds.size(), -1) < 0) {
            if (errno == EINTR) {
                continue;
            }
            failWith("poll", errno);
        }
        for (std::size_t i = 0; i < fds.size(); ++i) {
            if (fds[i].fd < 0 || fds[i].revents == 0) {
                continue;
            }
            ssize_t n = ::read(fds[i].fd, buffer, sizeof buffer);
            if (n > 0) {
                sinks[i]->append(buffer, static_cast<std::size_t>(n));
            } else if (n == 0 || errno != EINTR) {
                fds[i].fd = -1; // end of file (or a broken pipe): stop polling it
                --open;
            }
        }
    }
}

} // namespace

ProcessResult runProcess(const std::string& program, const std::vector<std::string>& args,
                         const std::string& workingDirectory) {
    Pipe out;
    Pipe err;
    SpawnActions actions;
    posix_spawn_file_actions_adddup2(actions.get(), out.writeEnd(), STDOUT_FILENO);
    posix_spawn_file_actions_adddup2(actions.get(), err.writeEnd(), STDERR_FILENO);
    posix_spawn_file_actions_addclose(actions.get(), out.readEnd());
    posix_spawn_file_actions_addclose(actions.get(), err.readEnd());
    if (!workingDirectory.empty()) {
        posix_spawn_file_actions_addchdir_np(actions.get(), workingDirectory.c_str());
    }

    std::vector<std::string> storage;
    storage.reserve(args.size() + 1);
    storage.push_back(program);
    storage.insert(storage.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (std::string& s : storage) {
        argv.push_back(s.data());
    }
    argv.push_back(nullptr);

    pid_t pid = 0;
    if (int error = posix_spawn(&pid, program.c_str(), actions.get(), nullptr, argv.data(), environ)) {
        failWith(("cannot start " + program).c_str(), error);
    }
    out.closeWrite();
    err.closeWrite();

    ProcessResult result;
    drain(out, err, result);
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0) {
        if (errno != EINTR) {
            failWith("waitpid", errno);
        }
    }
    result.exitStatus = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    return result;
}

std::string testNameFor(const std::string& name) {
    std::string out = name;
    std::replace_if(out.begin(), out.end(), [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); }, '_');
    return out;
}

} // namespace m350::testing
