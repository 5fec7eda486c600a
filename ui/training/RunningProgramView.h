#pragma once

#include "ui/session/PanelSnapshot.h"

#include <QDateTime>
#include <QString>
#include <QWidget>

#include <memory>

class QLabel;

namespace m350::gcode {
struct Dialect;
}

namespace m350::ui {

class CodeView;

// The review's program view: the file the machine runs (the loaded program, a macro library such
// as slib-g.nc while O20000 changes the tool, a hook file, the MDI lines) in the editor's code
// view, read-only, its running line highlighted and kept in sight, under the file's name and line.
// When nothing runs it keeps the last file shown, no line highlighted. A file is read again when
// it changed on disk (a trainee's repair of a macro line shows in the next run).
class RunningProgramView : public QWidget {
    Q_OBJECT
public:
    RunningProgramView(const gcode::Dialect& dialect, QString machineFolder, QWidget* parent = nullptr);
    void render(const PanelSnapshot& snapshot);
    void retranslate();

    CodeView* code() const { return code_; }
    QString fileName() const { return name_; } // as the run names it ("slib-g.nc", "MDI"), empty: none yet
    int runningLine() const;                    // 0: no block runs
    QString runningText() const;                // the highlighted line's text
    QString captionText() const;

protected:
    void changeEvent(QEvent* event) override;
    void showEvent(QShowEvent* event) override;

private:
    void show(const QString& name, const PanelSnapshot& snapshot);
    QString machineFolder_;
    QLabel* caption_;
    QLabel* machine_; // the spindle's tool and the machine position: where the line takes it
    CodeView* code_;
    QString name_;
    QString path_; // the file shown (empty for MDI lines)
    QDateTime modified_;
    qint64 size_ = -1;
    bool unreadable_ = false;
    std::shared_ptr<const QStringList> mdi_;
};

} // namespace m350::ui
