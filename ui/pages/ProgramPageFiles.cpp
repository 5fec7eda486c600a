// The Program page's file softkeys: 新建 删除 重命名 拷贝 粘贴 清除本地, with the panel's prompts.
#include "ui/pages/ProgramPage.h"

#include "ui/pages/PanelContext.h"
#include "ui/program/ProgramList.h"

#include <QDir>
#include <QFileInfo>

namespace m350::ui {

QString ProgramPage::nameProblemText(ProgramFiles::NameProblem problem) const {
    switch (problem) {
    case ProgramFiles::NameProblem::TooLong: return tr("File name is too long!", "msg 797");
    case ProgramFiles::NameProblem::Exists: return tr("File exists, please re-enter!", "msg 803");
    case ProgramFiles::NameProblem::Invalid: return tr("A file name may not begin with a dot or hold / : * ? < > | or a quote");
    case ProgramFiles::NameProblem::Empty:
    case ProgramFiles::NameProblem::None: break;
    }
    return {};
}

// 请输入文件名: until the name is free in `folder` (Esc or an empty name gives up).
void ProgramPage::askName(const QString& question, const QString& initial, const QString& folder,
                          std::function<void(const QString&)> done) {
    context().askText(question, initial, [=, this](std::optional<QString> text) {
        if (!text || text->trimmed().isEmpty()) {
            return;
        }
        const QString name = text->trimmed();
        ProgramFiles::NameProblem problem = ProgramFiles::checkName(folder, name);
        if (problem != ProgramFiles::NameProblem::None) {
            context().notify(nameProblemText(problem));
            askName(nameProblemText(problem) + QStringLiteral("\n") + question, name, folder, done);
            return;
        }
        done(name);
    });
}

void ProgramPage::newFile() {
    const QString folder = list_->folder();
    askName(tr("Pls enter the file name:", "msg 804"), {}, folder, [this, folder](const QString& name) {
        QString error;
        const QString path = QDir(folder).filePath(name);
        if (!ProgramFiles::create(path, &error)) {
            context().notify(tr("File save failed!", "msg 907") + QStringLiteral(" ") + error);
            return;
        }
        list_->refresh();
        list_->select(name);
        openEditor(path);
    });
}

void ProgramPage::deleteFile() {
    const QString path = list_->selectedPath();
    if (path.isEmpty()) {
        return;
    }
    if (snapshot_ && busyWith(path)) {
        context().notify(tr("Current file is running,can't delete!", "msg 871"));
        return;
    }
    context().ask(tr("Do you want to delete the selected file?", "msg 957") + QStringLiteral("\n") +
                      QFileInfo(path).fileName(),
                  [this, path](bool yes) {
                      QString error;
                      if (yes && !ProgramFiles::remove(path, &error)) {
                          context().notify(error);
                      }
                      list_->refresh();
                  });
}

void ProgramPage::renameFile() {
    const QString path = list_->selectedPath();
    if (path.isEmpty()) {
        return;
    }
    if (snapshot_ && busyWith(path)) {
        context().notify(tr("Current file is running,can't delete!", "msg 871"));
        return;
    }
    const QString folder = list_->folder();
    askName(tr("Pls enter the file name:", "msg 804"), QFileInfo(path).fileName(), folder,
            [this, path, folder](const QString& name) {
                QString error;
                if (!ProgramFiles::rename(path, QDir(folder).filePath(name), &error)) {
                    context().notify(error);
                }
                list_->refresh();
                list_->select(name);
            });
}

void ProgramPage::copyToOtherDisk() {
    const QString from = list_->selectedPath();
    if (from.isEmpty()) {
        return;
    }
    const ProgramFiles::Disk other =
        list_->disk() == ProgramFiles::Disk::User ? ProgramFiles::Disk::Local : ProgramFiles::Disk::User;
    clipboard_ = from;
    copyInto(from, folderOf(other), false);
}

void ProgramPage::pasteFile() {
    if (clipboard_.isEmpty() || !QFileInfo::exists(clipboard_)) {
        context().notify(tr("file does not exist!", "msg 842"));
        return;
    }
    copyInto(clipboard_, list_->folder(), true);
}

// Copies `from` into `folder` under its own name, or asks for another when that one is taken.
void ProgramPage::copyInto(const QString& from, const QString& folder, bool selectCopy) {
    auto copy = [this, from, folder, selectCopy](const QString& target) {
        QString error;
        if (!ProgramFiles::copy(from, QDir(folder).filePath(target), &error)) {
            context().notify(error);
            return;
        }
        context().notify(tr("Copy successful!", "msg 955"));
        list_->refresh();
        if (selectCopy) {
            list_->select(target);
        }
    };
    const QString name = QFileInfo(from).fileName();
    if (ProgramFiles::checkName(folder, name) == ProgramFiles::NameProblem::None) {
        copy(name);
    } else {
        askName(tr("File exists, please re-enter!", "msg 803"), {}, folder, copy);
    }
}

void ProgramPage::clearLocal() {
    context().ask(tr("Delete all?", "msg 846"), [this](bool yes) {
        if (!yes) {
            return;
        }
        for (const QString& name : list_->names()) {
            const QString path = QDir(localFolder_).filePath(name);
            QString error;
            if (snapshot_ && busyWith(path)) {
                context().notify(tr("Current file is running,can't delete!", "msg 871"));
            } else if (!ProgramFiles::remove(path, &error)) {
                context().notify(error);
            }
        }
        list_->refresh();
    });
}

} // namespace m350::ui
