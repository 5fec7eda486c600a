// The program editor on a 100,000-line program (about 2.6 MB): opening it (read, decode, fill
// the view, the comment state of every line, the first screen coloured), scrolling a screen
// further (what one wheel step costs), the scanner alone over every line, and the parser's check.
#include "core/config/MachineConfig.h"
#include "ui/program/CodeView.h"
#include "ui/program/GcodeHighlighter.h"
#include "ui/program/GcodeSyntax.h"
#include "ui/program/ProgramChecker.h"
#include "ui/program/ProgramEditor.h"

#include <QApplication>
#include <QDir>
#include <QFile>
#include <QScrollBar>
#include <QTemporaryDir>

#include <benchmark/benchmark.h>

#include <variant>

namespace {

constexpr int kLines = 100'000;

QString programText() {
    QString text;
    text.reserve(kLines * 28);
    for (int i = 0; i < kLines; ++i) {
        switch (i % 4) {
        case 0: text += QStringLiteral("G1 X%1 Y%2 F3000 (cut)\n").arg(i % 300).arg(i % 170); break;
        case 1: text += QStringLiteral("#101 = #101 + 1 // count\n"); break;
        case 2: text += QStringLiteral("IF [#101 GT %1] GOTO 10\n").arg(i); break;
        default: text += QStringLiteral("G0 Z5 M3 S12000\n"); break;
        }
    }
    return text;
}

m350::config::MachineConfig defaultMachine() {
    auto loaded = m350::config::loadMachineFolder(
        QDir(QString::fromStdString(m350::config::bundledMachinesDirectory())).filePath("m350-linear16").toStdString());
    return std::get<m350::config::MachineConfig>(std::move(loaded));
}

void OpenAndHighlight100kLines(benchmark::State& state) {
    const m350::config::MachineConfig machine = defaultMachine();
    QTemporaryDir dir;
    const QString path = dir.filePath("big.nc");
    QFile file(path);
    file.open(QIODevice::WriteOnly);
    file.write(programText().toUtf8());
    file.close();
    m350::ui::ProgramEditor editor(*machine.dialect, machine.libraries);
    editor.resize(640, 400);
    editor.show();
    for (auto _ : state) {
        QString error;
        bool ok = editor.open(path, &error);
        QApplication::processEvents();
        benchmark::DoNotOptimize(ok);
    }
    state.SetItemsProcessed(state.iterations() * kLines);
}
BENCHMARK(OpenAndHighlight100kLines)->Unit(benchmark::kMillisecond);

void ScrollOneScreen(benchmark::State& state) {
    const m350::config::MachineConfig machine = defaultMachine();
    m350::ui::CodeView view(*machine.dialect);
    view.resize(640, 400);
    view.show();
    view.setProgram(programText());
    QApplication::processEvents();
    QScrollBar* bar = view.verticalScrollBar();
    int step = bar->pageStep();
    for (auto _ : state) {
        bar->setValue(bar->value() + step >= bar->maximum() ? 0 : bar->value() + step);
        view.viewport()->repaint();
    }
}
BENCHMARK(ScrollOneScreen)->Unit(benchmark::kMicrosecond);

void ScanEveryLine(benchmark::State& state) {
    const m350::config::MachineConfig machine = defaultMachine();
    const QStringList lines = programText().split('\n');
    m350::ui::GcodeSyntax syntax(*machine.dialect);
    std::vector<m350::ui::GcodeSyntax::Span> spans;
    for (auto _ : state) {
        bool comment = false;
        for (const QString& line : lines) {
            comment = syntax.scan(line, comment, spans);
        }
        benchmark::DoNotOptimize(spans.data());
    }
    state.SetItemsProcessed(state.iterations() * lines.size());
}
BENCHMARK(ScanEveryLine)->Unit(benchmark::kMillisecond);

void Check100kLines(benchmark::State& state) {
    const m350::config::MachineConfig machine = defaultMachine();
    const QString text = programText();
    for (auto _ : state) {
        auto marks = m350::ui::ProgramChecker::diagnose(*machine.dialect, machine.libraries, "big.nc", text);
        benchmark::DoNotOptimize(marks.data());
    }
    state.SetItemsProcessed(state.iterations() * kLines);
}
BENCHMARK(Check100kLines)->Unit(benchmark::kMillisecond);

} // namespace

int main(int argc, char** argv) {
    qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
