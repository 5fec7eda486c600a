#include "ui/pages/BreakRunPage.h"

#include "ui/pages/CompactDro.h"
#include "ui/pages/PanelContext.h"
#include "ui/widgets/MeasuredLabel.h"

#include <QFileInfo>
#include <QLabel>
#include <QRegularExpression>
#include <QVBoxLayout>

namespace m350::ui {

namespace {

// The firmware's printf texts: each %d / %s in turn takes the next value.
QString printfText(QString format, const QStringList& values) {
    for (const QString& value : values) {
        qsizetype at = format.indexOf(QRegularExpression(QStringLiteral("%[ds]")));
        if (at < 0) {
            break;
        }
        format.replace(at, 2, value);
    }
    return format;
}

QString fileName(const QString& path) { return path.isEmpty() ? QStringLiteral("-") : QFileInfo(path).fileName(); }

} // namespace

BreakRunPage::BreakRunPage(PanelContext& context, QWidget* parent) : Page(context, parent) {
    setObjectName("breakRunPage");
    auto* column = new QVBoxLayout(this);
    column->setContentsMargins(8, 8, 8, 8);
    text_ = new MeasuredLabel(this);
    text_->setObjectName("breakPoints");
    text_->setStyleSheet(QStringLiteral("font-size: 13pt;"));
    column->addWidget(text_);
    dro_ = new CompactDro(this);
    column->addWidget(dro_);
    column->addStretch(1);
    retranslate();
}

QString BreakRunPage::title() const { return tr("Break Run", "msg 317"); }

void BreakRunPage::retranslate() {
    if (auto s = context().snapshot()) {
        render(*s);
    }
}

QVector<Page::Softkey> BreakRunPage::softkeys() const {
    return {{tr("Start Line", "msg 456"), true, {}},
            {tr("Power Resume", "msg 457"), true, {}},
            {tr("Pause Resume", "msg 458"), true, {}},
            {},
            {},
            {}};
}

// 文件扫描并定位成功,是否进行启动加工?/[file L:n]: Enter starts, Esc does nothing.
void BreakRunPage::confirm(const QString& file, int line, std::function<void()> start) {
    QString where = QStringLiteral("%1 L:%2").arg(fileName(file)).arg(line);
    QString question = printfText(tr("Breakpoint find out, do you want to start ?/[%s]", "msg 860").trimmed(), {where});
    context().ask(question.replace(QLatin1Char('/'), QLatin1Char('\n')), [start = std::move(start)](bool yes) {
        if (yes) {
            start();
        }
    });
}

void BreakRunPage::softkey(int number) {
    auto snapshot = context().snapshot();
    if (!snapshot) {
        return;
    }
    const BreakPoints& points = snapshot->breakPoints;
    const QString file = snapshot->programFile;
    if (number == 1) {
        if (file.isEmpty()) {
            context().notify(tr("No program loaded: load one on the Program page"));
            return;
        }
        const QString initial = points.pauseLine > 0 ? QString::number(points.pauseLine) : QString();
        context().askText(tr("Start line no.:", "msg 94"), initial, [this, file](std::optional<QString> text) {
            bool ok = false;
            int line = text ? text->trimmed().toInt(&ok) : 0;
            if (!text) {
                return;
            }
            if (!ok || line <= 0) {
                context().notify(tr("Line %1 is not in the program").arg(text->trimmed()));
                return;
            }
            confirm(file, line, [this, line] { context().session().startAtLine(line); });
        });
    } else if (number == 2) {
        if (points.keptLine <= 0) {
            context().notify(tr("No break point is kept in the machine folder"));
            return;
        }
        confirm(points.keptFile, points.keptLine, [this] { context().session().powerResume(); });
    } else if (number == 3) {
        if (points.pauseLine <= 0) {
            context().notify(tr("No paused run to resume (PAUSE, then RESET)"));
            return;
        }
        confirm(points.pauseFile, points.pauseLine, [this] { context().session().resumeAtPause(); });
    }
}

bool BreakRunPage::key(const QString& name) {
    if (name == QLatin1String("ESC")) {
        emit navigate(PageId::monitor);
        return true;
    }
    return false;
}

void BreakRunPage::render(const PanelSnapshot& snapshot) {
    const BreakPoints& p = snapshot.breakPoints;
    auto point = [](int slot, const QString& file, int line) {
        if (line <= 0) {
            return QStringLiteral("-");
        }
        return printfText(tr("BreakPoint%d:%s L:%d", "msg 102"), {QString::number(slot), fileName(file), QString::number(line)});
    };
    QStringList lines{tr("Current file:", "msg 876") + QLatin1Char(' ') + fileName(snapshot.programFile),
                      tr("Pause Resume", "msg 458") + QStringLiteral(": ") + point(1, p.pauseFile, p.pauseLine),
                      tr("Power Resume", "msg 457") + QStringLiteral(": ") + point(2, p.keptFile, p.keptLine)};
    text_->setText(lines.join(QLatin1Char('\n')));
    dro_->render(snapshot);
}

QJsonObject BreakRunPage::state() const { return {{"break_points", text_->text()}}; }

} // namespace m350::ui
