#include "ui/session/PreviewJob.h"

namespace m350::ui {

PreviewJob::PreviewJob(config::MachineConfig config, std::string program, std::optional<int> tool, Done done) {
    thread_ = std::thread([this, config = std::move(config), program = std::move(program), tool, done = std::move(done)]() mutable {
        preview::PreviewSettings settings;
        settings.cancel = &cancel_;
        settings.tool = tool;
        auto built = std::make_shared<preview::Preview>(preview::buildPreview(std::move(config), program, settings));
        if (!built->cancelled) {
            result_ = built;
            if (done) {
                done(std::move(built));
            }
        }
    });
}

PreviewJob::~PreviewJob() {
    cancel_.store(true, std::memory_order_relaxed);
    wait();
}

void PreviewJob::wait() {
    if (thread_.joinable()) {
        thread_.join();
    }
}

} // namespace m350::ui
