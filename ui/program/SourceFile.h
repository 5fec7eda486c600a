#pragma once

#include <QString>

#include <optional>

namespace m350::ui {

// A program file as the editor holds it: its text, and the encoding it is written back in. The
// panel's own files are GBK, a PC's are UTF-8; a file keeps the encoding it came in.
struct SourceFile {
    enum class Encoding { Utf8, Gbk };
    QString path;
    QString text;
    Encoding encoding = Encoding::Utf8;
    bool bom = false;  // a UTF-8 file that began with a BOM keeps it
    bool crlf = false; // lines end in CR LF (the editor holds LF only)
    bool cr = false;   // lines end in CR alone (old Mac files, some panel exports)

    // Reads and decodes as the parser does (core/gcode/SourceText: strict UTF-8, else GBK).
    static std::optional<SourceFile> read(const QString& path, QString* error);
    // Encodes `text` in the file's encoding and replaces the file atomically (QSaveFile).
    bool write(QString* error) const;
    QByteArray encode(QString* error) const;
};

} // namespace m350::ui
