#pragma once

#include "core/backup/BackupImport.h"

#include <QObject>
#include <QString>

#include <functional>
#include <variant>

class QThread;
class QWidget;

namespace m350::ui {

class PanelContext;

// The panel's 导入控制器备份 (Import controller backup...), the Panel menu's counterpart of
// `m350-sim import`: choose the backup folder and a new machine folder, import (core/backup/
// BackupImport), show what was made and what to review in the panel's prompt, then offer to
// switch the panel to the new machine when the application can (setSwitcher). The import reads
// and writes files, so it runs on a thread of its own: the panel keeps drawing and answering keys.
class BackupImportFlow : public QObject {
    Q_OBJECT
public:
    // Asks for a folder: an existing one (the backup), or the path of one to create. Empty: cancelled.
    using FolderChooser = std::function<QString(const QString& caption, const QString& start, bool existing)>;
    using Switcher = std::function<void(const QString& machineFolder)>;

    BackupImportFlow(PanelContext& context, QWidget* window);
    ~BackupImportFlow() override; // waits for an import under way

    void setFolderChooser(FolderChooser chooser) { chooser_ = std::move(chooser); } // tests; default: file dialogs
    void setSwitcher(Switcher switcher) { switcher_ = std::move(switcher); }         // none: the panel cannot switch

    void start(); // the menu entry
    void importInto(const QString& backup, const QString& machineFolder); // returns at once
    bool importing() const { return worker_ != nullptr; }
    bool waitForImport(int milliseconds); // tests: true when no import is under way any more

signals:
    void importFinished(); // the report or the refusal is in the prompt

private:
    QString chooseFolder(const QString& caption, const QString& start, bool existing) const;
    void report(const std::variant<backup::BackupImport, backup::ImportError>& outcome);
    QThread* worker_ = nullptr;
    PanelContext& context_;
    QWidget* window_;
    FolderChooser chooser_;
    Switcher switcher_;
};

} // namespace m350::ui
