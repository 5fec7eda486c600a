#include "ui/session/BreakPointFile.h"

#include "ui/i18n/Language.h"

#include "core/config/MachineFolder.h"
#include "core/controller/BreakRun.h"

#include <QFile>

namespace m350::ui {

std::optional<QString> BreakPointFile::keep(const controller::BreakRun& run, const config::MachineFolder& folder) {
    auto point = run.pauseBreakPoint();
    if (!point) {
        return std::nullopt;
    }
    const std::string text = point->file + '\n' + std::to_string(point->line) + '\n';
    if (auto problem = folder.write(config::FolderFile::BreakPoint, text)) {
        return QString::fromStdString(problem->in(Language::messageLanguage()));
    }
    kept_ = std::make_pair(QString::fromStdString(point->file), static_cast<int>(point->line));
    return std::nullopt;
}

BreakPoints BreakPointFile::points(const controller::BreakRun& run, const config::MachineFolder& folder) const {
    BreakPoints out;
    if (auto point = run.pauseBreakPoint()) {
        out.pauseFile = QString::fromStdString(point->file);
        out.pauseLine = static_cast<int>(point->line);
    }
    if (!kept_) {
        kept_.emplace();
        QFile file(QString::fromStdString(folder.pathOf(config::FolderFile::BreakPoint).string()));
        QList<QByteArray> lines = file.open(QIODevice::ReadOnly) ? file.readAll().split('\n') : QList<QByteArray>{};
        if (lines.size() >= 2) {
            *kept_ = {QString::fromUtf8(lines[0]), lines[1].trimmed().toInt()};
        }
    }
    out.keptFile = kept_->first;
    out.keptLine = kept_->second;
    return out;
}

} // namespace m350::ui
