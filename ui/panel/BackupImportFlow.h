#pragma once

#include <QObject>
#include <QString>

#include <functional>

class QWidget;

namespace m350::ui {

class PanelContext;

// The panel's 导入控制器备份 (Import controller backup...), the Panel menu's counterpart of
// `m350-sim import`: choose the backup folder and a new machine folder, import (core/config/
// BackupImport), show what was made and what to review in the panel's prompt, then offer to
// switch the panel to the new machine when the application can (setSwitcher).
class BackupImportFlow : public QObject {
    Q_OBJECT
public:
    // Asks for a folder: an existing one (the backup), or the path of one to create. Empty: cancelled.
    using FolderChooser = std::function<QString(const QString& caption, const QString& start, bool existing)>;
    using Switcher = std::function<void(const QString& machineFolder)>;

    BackupImportFlow(PanelContext& context, QWidget* window);

    void setFolderChooser(FolderChooser chooser) { chooser_ = std::move(chooser); } // tests; default: file dialogs
    void setSwitcher(Switcher switcher) { switcher_ = std::move(switcher); }         // none: the panel cannot switch

    void start(); // the menu entry
    void importInto(const QString& backup, const QString& machineFolder);

private:
    QString chooseFolder(const QString& caption, const QString& start, bool existing) const;
    PanelContext& context_;
    QWidget* window_;
    FolderChooser chooser_;
    Switcher switcher_;
};

} // namespace m350::ui
