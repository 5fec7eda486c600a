#include "ui/panel/BackupImportFlow.h"

#include "core/backup/BackupImport.h"
#include "ui/i18n/Language.h"
#include "ui/pages/PanelContext.h"

#include <QCoreApplication>
#include <QDeadlineTimer>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QThread>

#include <memory>

namespace m350::ui {

namespace {

constexpr int kUnsupportedShown = 3; // the rest is in import-report.txt
constexpr int kLineLength = 200;

QString shortLine(const std::string& line) {
    QString text = QString::fromStdString(line);
    return text.size() > kLineLength ? text.left(kLineLength - 1) + QChar(0x2026) : text;
}

} // namespace

BackupImportFlow::BackupImportFlow(PanelContext& context, QWidget* window)
    : QObject(window), context_(context), window_(window) {}

BackupImportFlow::~BackupImportFlow() {
    if (worker_) {
        worker_->wait();
    }
}

bool BackupImportFlow::waitForImport(int milliseconds) {
    QDeadlineTimer deadline(milliseconds);
    while (worker_ && !deadline.hasExpired()) {
        QCoreApplication::processEvents(QEventLoop::AllEvents, 10);
    }
    return worker_ == nullptr;
}

QString BackupImportFlow::chooseFolder(const QString& caption, const QString& start, bool existing) const {
    if (chooser_) {
        return chooser_(caption, start, existing);
    }
    return existing ? QFileDialog::getExistingDirectory(window_, caption, start)
                    : QFileDialog::getSaveFileName(window_, caption, start, {}, nullptr,
                                                   QFileDialog::DontConfirmOverwrite | QFileDialog::ShowDirsOnly);
}

void BackupImportFlow::start() {
    const QString backup = chooseFolder(tr("Controller backup: the folder that holds setting, slib-g.nc ..."),
                                        QDir::homePath(), true);
    if (backup.isEmpty()) {
        return;
    }
    const QString machines = QFileInfo(context_.machineFolder()).absolutePath();
    const QString into = chooseFolder(tr("New machine folder (a new or empty folder)"),
                                      QDir(machines).filePath(QFileInfo(backup).fileName()), false);
    if (!into.isEmpty()) {
        importInto(backup, into);
    }
}

void BackupImportFlow::importInto(const QString& backup, const QString& machineFolder) {
    if (worker_) {
        context_.notify(tr("An import is under way: wait for its report"));
        return;
    }
    context_.notify(tr("Importing %1 ...").arg(backup));
    using Outcome = std::variant<backup::BackupImport, backup::ImportError>;
    auto outcome = std::make_shared<Outcome>();
    worker_ = QThread::create([outcome, from = backup.toStdString(), into = machineFolder.toStdString(),
                               language = Language::messageLanguage()] {
        *outcome = backup::importControllerBackup(from, into, language);
    });
    connect(worker_, &QThread::finished, this, [this, outcome] {
        worker_->deleteLater();
        worker_ = nullptr;
        report(*outcome);
        emit importFinished();
    });
    worker_->start();
}

void BackupImportFlow::report(const std::variant<backup::BackupImport, backup::ImportError>& outcome) {
    if (auto* error = std::get_if<backup::ImportError>(&outcome)) {
        context_.ask(tr("Import refused:\n%1: %2")
                         .arg(QString::fromStdString(error->file), QString::fromStdString(error->message.in(Language::messageLanguage()))),
                     [](bool) {});
        return;
    }
    const backup::BackupImport& r = std::get<backup::BackupImport>(outcome);
    const QString folder = QString::fromStdString(r.machineFolder);
    QStringList lines;
    lines << (r.unchanged ? tr("%1 already holds this backup's import; nothing written").arg(folder)
                          : tr("Machine folder made from the backup:\n%1").arg(folder));
    const MessageLanguage language = Language::messageLanguage();
    lines << shortLine(r.magazine.in(language));
    if (r.factoryCompared) {
        lines << tr("%1 parameters, %2 differ from the factory values").arg(r.parameters).arg(r.changedParameters.size());
    }
    lines << tr(".nc files copied as they were: %1; other files not copied: %2").arg(r.copied.size()).arg(r.skipped.size());
    lines << tr("%1 stated values to review in machine.toml").arg(r.review.size());
    if (!r.unsupported.empty()) {
        lines << tr("The simulator cannot model:");
        for (std::size_t i = 0; i < r.unsupported.size() && i < kUnsupportedShown; ++i) {
            lines << QStringLiteral("- ") + shortLine(r.unsupported[i].in(language));
        }
    }
    if (!r.diagnostics.empty()) {
        lines << tr("%1 syntax errors the simulator does not accept yet").arg(r.diagnostics.size());
    }
    lines << tr("The whole report: %1").arg(QString::fromLatin1(backup::kImportReportFile));
    if (!switcher_) {
        lines << QString() << tr("Open it with: m350-hmi --config %1").arg(folder);
        context_.ask(lines.join(QLatin1Char('\n')), [](bool) {});
        return;
    }
    lines << QString() << tr("Switch the panel to this machine now?");
    context_.ask(lines.join(QLatin1Char('\n')), [this, folder](bool yes) {
        if (yes && switcher_) {
            switcher_(folder);
        }
    });
}

} // namespace m350::ui
