#include "ui/pages/MdiLines.h"

#include "core/config/MachineFolder.h"
#include "ui/i18n/Language.h"

#include <QFile>
#include <QStringDecoder>

namespace m350::ui {

QString MdiLines::path(const QString& folder) {
    return QString::fromStdString(config::MachineFolder(folder.toStdString()).pathOf(config::FolderFile::MdiBlock).string());
}

namespace {

QString decode(const QByteArray& bytes) {
    QStringDecoder utf8(QStringDecoder::Utf8, QStringDecoder::Flag::Stateless);
    QString text = utf8.decode(bytes);
    if (!utf8.hasError()) {
        return text;
    }
    QStringDecoder gbk("GB18030"); // the panel's own files are GBK; GB18030 reads it
    return gbk.isValid() ? QString(gbk.decode(bytes)) : QString::fromLatin1(bytes);
}

} // namespace

QStringList MdiLines::load(const QString& folder, QString* error) {
    QStringList lines;
    QFile file(path(folder));
    QByteArray bytes;
    if (file.exists()) {
        if (file.open(QIODevice::ReadOnly)) {
            bytes = file.readAll();
        } else if (error) {
            *error = QStringLiteral("%1: cannot read: %2").arg(file.fileName(), file.errorString());
        }
    }
    for (int i = 0; i < kCount; ++i) {
        QByteArray record = bytes.mid(i * kRecordBytes, kRecordBytes);
        qsizetype end = record.indexOf('\0');
        lines << decode(end < 0 ? record : record.left(end)).trimmed();
    }
    return lines;
}

bool MdiLines::save(const QString& folder, const QStringList& lines, QString* error) {
    QByteArray bytes(kCount * kRecordBytes, '\0');
    for (int i = 0; i < kCount && i < lines.size(); ++i) {
        QByteArray line = lines[i].toUtf8();
        if (line.size() >= kRecordBytes) {
            *error = QStringLiteral("MDI line %1 is %2 bytes long; the panel keeps at most %3")
                         .arg(i + 1)
                         .arg(line.size())
                         .arg(kRecordBytes - 1);
            return false;
        }
        bytes.replace(i * kRecordBytes, line.size(), line);
    }
    // as every machine folder file: a temp file, fsync, rename, fsync of the folder
    const std::string_view content(bytes.constData(), static_cast<std::size_t>(bytes.size()));
    if (auto problem = config::MachineFolder(folder.toStdString()).write(config::FolderFile::MdiBlock, content)) {
        *error = QString::fromStdString(problem->in(Language::messageLanguage()));
        return false;
    }
    return true;
}

} // namespace m350::ui
