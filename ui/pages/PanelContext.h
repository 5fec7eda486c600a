#pragma once

#include "ui/pages/PanelPrompt.h"
#include "ui/session/MachineSession.h"

#include "core/config/MachineFolder.h"

#include <QString>

#include <functional>
#include <optional>

namespace m350::ui {

// What a page may use: the machine session (queued commands), the latest snapshot, the prompt
// box, the panel's own message line, and the machine folder (for files the panel keeps there).
class PanelContext {
public:
    PanelContext(MachineSession& session, QString machineFolder)
        : session_(session), machineFolder_(std::move(machineFolder)) {}

    MachineSession& session() const { return session_; }
    SnapshotPtr snapshot() const { return session_.latest(); }
    const QString& machineFolder() const { return machineFolder_; }
    // The machine folder's store: a page writes a file there only through it.
    config::MachineFolder folderFiles() const { return config::MachineFolder(machineFolder_.toStdString()); }

    // A yes/no question (Enter = yes).
    void ask(const QString& question, std::function<void(bool)> answer) const;
    // A value to type; nullopt when the operator pressed Esc.
    void askText(const QString& question, const QString& initial,
                 std::function<void(std::optional<QString>)> answer) const;
    // A password: typed as dots.
    void askSecret(const QString& question, std::function<void(std::optional<QString>)> answer) const;
    // A line on the message line (the panel's own notices, beside the macro's #1503 text).
    void notify(const QString& text) const {
        if (notify_) {
            notify_(text);
        }
    }

    void attach(PanelPrompt* prompt, std::function<void(const QString&)> notify) {
        prompt_ = prompt;
        notify_ = std::move(notify);
    }

private:
    MachineSession& session_;
    QString machineFolder_;
    PanelPrompt* prompt_ = nullptr;
    std::function<void(const QString&)> notify_;
};

} // namespace m350::ui
