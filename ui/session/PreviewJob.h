#pragma once

#include "core/config/MachineConfig.h"
#include "core/preview/PreviewBuilder.h"

#include <atomic>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <thread>

namespace m350::ui {

// Builds one preview on a thread of its own (core/preview/PreviewBuilder.h), so the panel answers
// keys while a million-line program is run through. `done` is called on that thread with the
// result (none: the caller waits). Destroying the job cancels the build and waits for the thread.
class PreviewJob {
public:
    using Done = std::function<void(std::shared_ptr<const preview::Preview>)>;
    // `tool`: in the spindle at the start, as on the machine the program will run on.
    PreviewJob(config::MachineConfig config, std::string program, std::optional<int> tool, Done done);
    ~PreviewJob();
    PreviewJob(const PreviewJob&) = delete;
    PreviewJob& operator=(const PreviewJob&) = delete;

    // Waits until the build ends (done has been called): a manual clock's replay stays deterministic.
    void wait();
    // After wait(): what was built (null when cancelled).
    std::shared_ptr<const preview::Preview> result() const { return result_; }

private:
    std::atomic<bool> cancel_{false};
    std::shared_ptr<const preview::Preview> result_;
    std::thread thread_;
};

} // namespace m350::ui
