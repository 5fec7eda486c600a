#include "ui/program/ProgramChecker.h"
#include "ui/i18n/DiagnosticText.h"

#include "core/check/TraineeLint.h"
#include "core/gcode/Parser.h"
#include "core/gcode/SourceText.h"

#include <QFileInfo>
#include <QMetaObject>

#include <variant>

namespace m350::ui {

ProgramChecker::ProgramChecker(const gcode::Dialect& dialect, std::vector<config::LibraryFile> libraries,
                               QObject* parent)
    : QObject(parent), dialect_(dialect), libraries_(std::move(libraries)) {
    timer_.setSingleShot(true);
    timer_.setInterval(kPauseMs);
    connect(&timer_, &QTimer::timeout, this, &ProgramChecker::run);
    pool_.setMaxThreadCount(1);
}

ProgramChecker::~ProgramChecker() { pool_.waitForDone(); }

void ProgramChecker::schedule(const QString& path, const QString& text) {
    path_ = path;
    text_ = text;
    timer_.start();
}

void ProgramChecker::run() {
    const int generation = ++generation_;
    ++running_;
    pool_.start([this, generation, path = path_, text = text_] {
        QVector<CodeView::Mark> marks = diagnose(dialect_, libraries_, path, text);
        QMetaObject::invokeMethod(this, [this, generation, marks] {
            --running_;
            if (generation == generation_) {
                emit checked(marks);
            }
        }, Qt::QueuedConnection);
    });
}

QVector<CodeView::Mark> ProgramChecker::diagnose(const gcode::Dialect& dialect,
                                                 const std::vector<config::LibraryFile>& libraries,
                                                 const QString& path, const QString& text) {
    const std::string file = path.toStdString();
    const std::string name = QFileInfo(path).fileName().toStdString();
    const QString canonical = QFileInfo(path).canonicalFilePath();
    gcode::Program program;
    gcode::Parser parser(dialect);
    gcode::FileRole role = gcode::FileRole::Main;
    for (const config::LibraryFile& library : libraries) {
        if (!canonical.isEmpty() && QFileInfo(QString::fromStdString(library.path)).canonicalFilePath() == canonical) {
            role = library.role;
        }
    }
    const QByteArray utf8 = text.toUtf8();
    parser.addFile(program, file, std::string_view(utf8.constData(), static_cast<std::size_t>(utf8.size())), role);
    for (const config::LibraryFile& library : libraries) {
        if (QFileInfo(QString::fromStdString(library.path)).canonicalFilePath() == canonical) {
            continue; // the edited text stands in for it
        }
        auto source = gcode::readSourceFile(library.path);
        if (const auto* lib = std::get_if<gcode::SourceText>(&source)) {
            parser.addFile(program, lib->path, lib->text, library.role, std::string(gcode::encodingName(lib->encoding)));
        }
    }
    parser.finish(program);
    std::vector<gcode::Diagnostic> found = parser.diagnostics();
    if (!program.files.empty()) {
        const std::vector<gcode::Diagnostic> lints = check::TraineeLint(program, dialect).findings(0); // the edited text
        found.insert(found.end(), lints.begin(), lints.end());
    }
    QVector<CodeView::Mark> marks;
    for (const gcode::Diagnostic& d : found) {
        if (d.file == file || d.file == name) {
            marks.append({static_cast<int>(d.line), static_cast<int>(d.column), DiagnosticText::message(d)});
        }
    }
    return marks;
}

} // namespace m350::ui
