#include "ui/program/SourceFile.h"

#include "core/gcode/SourceText.h"

#include <QFile>
#include <QSaveFile>
#include <QStringEncoder>

#include <variant>

namespace m350::ui {

std::optional<SourceFile> SourceFile::read(const QString& path, QString* error) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        *error = QStringLiteral("%1: %2").arg(path, file.errorString());
        return std::nullopt;
    }
    QByteArray bytes = file.readAll();
    auto decoded = gcode::decodeSource(path.toStdString(), std::string_view(bytes.constData(), bytes.size()));
    if (auto* failed = std::get_if<gcode::SourceReadError>(&decoded)) {
        *error = QString::fromStdString(failed->path + ": " + failed->message);
        return std::nullopt;
    }
    const auto& source = std::get<gcode::SourceText>(decoded);
    SourceFile out;
    out.path = path;
    out.text = QString::fromUtf8(source.text.data(), static_cast<qsizetype>(source.text.size()));
    out.encoding = source.encoding == gcode::TextEncoding::Gbk ? Encoding::Gbk : Encoding::Utf8;
    out.bom = bytes.startsWith("\xEF\xBB\xBF");
    out.crlf = out.text.contains(QStringLiteral("\r\n"));
    if (out.crlf) {
        out.text.replace(QStringLiteral("\r\n"), QStringLiteral("\n"));
    }
    out.cr = !out.crlf && out.text.contains(QLatin1Char('\r'));
    out.text.replace(QLatin1Char('\r'), QLatin1Char('\n')); // a lone CR ends a line, as for the parser
    return out;
}

QByteArray SourceFile::encode(QString* error) const {
    QString lines = crlf ? QString(text).replace(QStringLiteral("\n"), QStringLiteral("\r\n"))
                    : cr ? QString(text).replace(QLatin1Char('\n'), QLatin1Char('\r'))
                         : text;
    if (encoding == Encoding::Utf8) {
        return (bom ? QByteArray("\xEF\xBB\xBF") : QByteArray()) + lines.toUtf8();
    }
    // GB18030 writes every GBK character as GBK does; Qt has it through ICU.
    QStringEncoder gbk("GB18030");
    if (!gbk.isValid()) {
        *error = QStringLiteral("this Qt has no GB18030 encoder (ICU): the GBK file is not written");
        return {};
    }
    return gbk.encode(lines);
}

bool SourceFile::write(QString* error) const {
    QString why;
    QByteArray bytes = encode(&why);
    if (!why.isEmpty()) {
        *error = why;
        return false;
    }
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(bytes) != bytes.size() || !file.commit()) {
        *error = QStringLiteral("%1: %2").arg(path, file.errorString());
        return false;
    }
    return true;
}

} // namespace m350::ui
