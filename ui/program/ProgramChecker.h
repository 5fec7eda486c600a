#pragma once

#include "ui/program/CodeView.h"

#include "core/config/MachineConfig.h"

#include <QObject>
#include <QThreadPool>
#include <QTimer>

#include <vector>

namespace m350::ui {

// `m350-sim check` for the editor: the text as it stands, parsed with the machine's dialect and
// macro libraries (the file being a library replaces that library). The Program page gives it
// config::parsingDialect, as the Controller parses: the codes that call macros take G65's argument
// rule in their blocks.
// Runs a pause after the last keystroke, in a thread of its own, and reports the findings about
// this file at their line and column, with the trainee lints of `check --lint` (check::TraineeLint).
class ProgramChecker : public QObject {
    Q_OBJECT
public:
    ProgramChecker(const gcode::Dialect& dialect, std::vector<config::LibraryFile> libraries, QObject* parent = nullptr);
    ~ProgramChecker() override;

    static constexpr int kPauseMs = 400;
    // The text changed: check it once the typing pauses (a newer text replaces a waiting one).
    void schedule(const QString& path, const QString& text);
    // Now, on this thread (tests and benchmarks).
    static QVector<CodeView::Mark> diagnose(const gcode::Dialect& dialect,
                                            const std::vector<config::LibraryFile>& libraries, const QString& path,
                                            const QString& text);
    const gcode::Dialect& dialect() const { return dialect_; }
    const std::vector<config::LibraryFile>& libraries() const { return libraries_; }
    bool pending() const { return timer_.isActive() || running_ > 0; }

signals:
    void checked(const QVector<m350::ui::CodeView::Mark>& marks);

private:
    void run();
    const gcode::Dialect dialect_; // a copy: a check still running on the pool outlives its page's members
    std::vector<config::LibraryFile> libraries_;
    QTimer timer_;
    QThreadPool pool_;
    QString path_;
    QString text_;
    int generation_ = 0;
    int running_ = 0;
};

} // namespace m350::ui
