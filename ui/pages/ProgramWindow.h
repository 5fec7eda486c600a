#pragma once

#include "ui/session/PanelSnapshot.h"

#include <QDateTime>
#include <QFrame>
#include <QHash>
#include <QStringList>

#include <array>
#include <memory>

class QLabel;

namespace m350::ui {

// The Monitor's program window: the program the machine runs (AUTO, MDI, 试切), a few lines
// around the running block with that block highlighted, under its file name and line number.
// When nothing runs it shows the top of the loaded program; after an alarm or an E-stop, the
// block the run stopped in. It reads a file only when the running file changes and redraws only
// when the running line does, so it costs nothing at 60 Hz.
class ProgramWindow : public QFrame {
    Q_OBJECT
public:
    // Rows shown: at least kRows, as many more as its height holds (the Monitor gives it the room
    // the DRO leaves), at most kMostRows; the running block is the middle one, when it can be.
    static constexpr int kRows = 5;
    static constexpr int kMostRows = 15;
    int rows() const { return rows_; }
    ProgramWindow(QString machineFolder, QWidget* parent = nullptr);
    void render(const PanelSnapshot& snapshot);
    void retranslate();

    int runningLine() const { return running_; } // 0: no block runs
    QString runningText() const;                // the highlighted row's text (empty: none)
    QString captionText() const;
    QString rowText(int row) const;             // "12  G01 X10", as shown
    bool rowHighlighted(int row) const;

    QSize minimumSizeHint() const override;
    QSize sizeHint() const override;

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    struct Source {
        QString key; // the path, or "MDI" with the lines' object
        QStringList lines;
        bool unreadable = false;
        QDateTime modified;
        qint64 size = -1;
    };
    void use(const QString& name, const PanelSnapshot& snapshot);
    void redraw();
    QString machineFolder_;
    QLabel* caption_;
    std::array<QLabel*, kMostRows> numbers_{};
    std::array<QLabel*, kMostRows> texts_{};
    int rows_ = kRows;
    void fitRows();
    Source source_;
    // Files read before, by path: a run that goes in and out of a library file (O20000 in
    // slib-g.nc) reads each once while it stays unchanged on disk.
    QHash<QString, Source> read_;
    std::shared_ptr<const QStringList> mdi_; // the MDI lines source_ was made from
    QString name_; // the file's name as the run reports it
    int running_ = 0;
    int first_ = 0; // the file line the top row shows (1-based; 0: empty window)
};

} // namespace m350::ui
