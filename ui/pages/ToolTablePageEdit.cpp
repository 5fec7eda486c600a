// What the tool table page's keys change: a field of the selected tool through the prompt, a new
// tool, a deleted one, touch off, and tool.tbl files read and written.
#include "ui/pages/ToolTablePage.h"

#include "core/controller/ParameterWrites.h"
#include "core/files/OutputGuard.h"
#include "core/tools/ToolData.h"
#include "core/tools/ToolTableFile.h"
#include "core/tools/ToolTableText.h"
#include "ui/i18n/Language.h"
#include "ui/pages/LevelPrompt.h"
#include "ui/pages/PanelContext.h"

#include <QDir>
#include <QFileInfo>
#include <QTableWidget>

#include <variant>

namespace m350::ui {

namespace {

std::optional<double> numberIn(const QString& text) { return tools::parseTableNumber(text.trimmed().toStdString()); }

// A type by its number in the prompt's list (1-11) or its key ("ball").
std::optional<tools::ToolType> typeIn(const QString& text) {
    bool isNumber = false;
    const int index = text.trimmed().toInt(&isNumber);
    if (isNumber && index >= 1 && index <= static_cast<int>(tools::kToolTypeCount)) {
        return static_cast<tools::ToolType>(index - 1);
    }
    return tools::toolTypeFromKey(text.trimmed().toLower().toStdString());
}

} // namespace

void ToolTablePage::edit() {
    if (auto entry = selectedEntry()) {
        editField(*entry, column_);
    }
}

void ToolTablePage::editField(const tools::ToolEntry& entry, Column column) {
    if (column == Column::Tool) {
        context().notify(tr("A tool keeps its number: add the new number with New and delete this one"));
        return;
    }
    // on the M350 a tool's Z is its parameter (930+): the level the Param page asks for it
    auto s = context().snapshot();
    const std::optional<int> z = column == Column::Z && s && s->tWordChangesTool
                                     ? tools::m350ZParameter(entry.tool, s->status.parameters)
                                     : std::nullopt;
    if (z && !LevelPrompt::require(context(), controller::ParameterWrites::required(*z),
                                   [this, entry, column] { editField(entry, column); })) {
        return;
    }
    QString question = QStringLiteral("T%1 %2").arg(entry.tool).arg(columnTitle(column));
    if (column == Column::Type) {
        QStringList choices;
        for (std::size_t i = 0; i < tools::kToolTypeCount; ++i) {
            choices << QStringLiteral("%1 %2").arg(i + 1).arg(typeName(static_cast<tools::ToolType>(i)));
        }
        question += QStringLiteral(" (") + choices.join(QStringLiteral(", ")) + QStringLiteral(")");
    }
    if (column != Column::Pocket) {
        question += QStringLiteral(" (") + tr("empty: none") + QStringLiteral(")");
    }
    const QString current = column != Column::Type ? cellText(table_->currentRow(), column)
                            : entry.type                ? QString::number(static_cast<int>(*entry.type) + 1)
                                                        : QString();
    context().askText(question + QStringLiteral(":"), current,
                      [this, entry, column](std::optional<QString> text) {
        if (!text) {
            return;
        }
        tools::ToolEntry changed = entry;
        const bool empty = text->trimmed().isEmpty();
        const std::optional<double> number = numberIn(*text);
        bool ok = empty || number.has_value();
        switch (column) {
        case Column::Pocket: {
            std::optional<int> pocket = tools::parseWholeNumber(text->trimmed().toStdString());
            ok = pocket.has_value();
            changed.pocket = pocket.value_or(entry.pocket);
            break;
        }
        case Column::Z: changed.offsets[tools::kZ] = empty ? std::nullopt : number; break;
        case Column::Diameter: changed.diameter = empty ? std::nullopt : number; break;
        case Column::Rpm: changed.maxRpm = empty ? std::nullopt : number; break;
        case Column::Teeth:
            changed.teeth = empty ? std::nullopt : tools::parseWholeNumber(text->trimmed().toStdString());
            ok = empty || changed.teeth.has_value();
            break;
        case Column::Type:
            changed.type = empty ? std::nullopt : typeIn(*text);
            ok = empty || changed.type.has_value();
            break;
        case Column::Comment:
            changed.comment = text->trimmed().toStdString();
            ok = true;
            break;
        case Column::Tool: break;
        }
        const std::optional<Message> invalid = ok ? tools::invalidEntry(changed) : std::nullopt;
        if (!ok || invalid) {
            const QString why = invalid ? QString::fromStdString(invalid->in(Language::messageLanguage())) : tr("not a valid value");
            context().notify(tr("T%1: %2").arg(entry.tool).arg(why));
            return;
        }
        context().session().putTool(changed);
        context().notify({});
    });
}

void ToolTablePage::addTool() {
    context().askText(tr("New tool number:"), {}, [this](std::optional<QString> text) {
        if (!text) {
            return;
        }
        std::optional<int> tool = tools::parseWholeNumber(text->trimmed().toStdString());
        if (!tool || *tool < 1) {
            context().notify(tr("Tool numbers start at 1"));
            return;
        }
        if (shown_ && shown_->find(*tool)) {
            context().notify(tr("T%1 is already in the table").arg(*tool));
            return;
        }
        std::optional<int> pocket = shown_ ? shown_->freePocket(*tool) : std::optional<int>(*tool);
        if (!pocket) {
            context().notify(tr("The tool table is full (1000 tools)"));
            return;
        }
        tools::ToolEntry entry;
        entry.tool = *tool;
        entry.pocket = *pocket;
        entry.offsets[tools::kZ] = 0.0;
        currentTool_ = *tool;
        context().session().putTool(entry);
        context().notify({});
    });
}

void ToolTablePage::removeSelected() {
    const int tool = selectedTool();
    if (tool == 0) {
        return;
    }
    context().ask(tr("Delete T%1 from the tool table?").arg(tool), [this, tool](bool yes) {
        if (yes) {
            context().session().removeTool(tool);
        }
    });
}

void ToolTablePage::touchOff() {
    auto s = context().snapshot();
    const int tool = s ? s->status.tool : 0;
    if (tool == 0) {
        context().notify(tr("The current tool No. is 0, this operation is invalid!", "msg 858"));
        return;
    }
    // the M350 keeps the tool's Z in a parameter (930+): the level the Param page asks for it
    const std::optional<int> z = s->tWordChangesTool ? tools::m350ZParameter(tool, s->status.parameters) : std::nullopt;
    if (z && !LevelPrompt::require(context(), controller::ParameterWrites::required(*z), [this] { touchOff(); })) {
        return;
    }
    context().askText(tr("Touch off T%1: the work Z of its tip (gauge or cut surface):").arg(tool), QStringLiteral("0"),
                      [this](std::optional<QString> text) {
        if (!text) {
            return;
        }
        std::optional<double> z = numberIn(*text);
        if (!z) {
            context().notify(tr("Not a number: %1").arg(*text));
            return;
        }
        context().session().touchOffTool(*z);
        context().notify({});
    });
}

QString ToolTablePage::resolvePath(const QString& typed) const {
    return QDir(context().machineFolder()).absoluteFilePath(typed.trimmed());
}

void ToolTablePage::importTable() {
    context().askText(tr("Import a tool.tbl (path; relative to the machine folder):"), {}, [this](std::optional<QString> text) {
        if (!text || text->trimmed().isEmpty()) {
            return;
        }
        const QString path = resolvePath(*text);
        auto read = tools::readToolTableFile(path.toStdString());
        if (auto* error = std::get_if<Message>(&read)) {
            context().notify(QString::fromStdString(error->in(Language::messageLanguage())));
            return;
        }
        auto parsed = std::make_shared<tools::ParsedToolTable>(std::get<tools::ParsedToolTable>(std::move(read)));
        QString skipped;
        int refused = 0;
        for (const tools::ToolTableIssue& issue : parsed->issues) {
            if (issue.severity == tools::ToolTableIssue::Severity::Error && refused++ == 0) {
                skipped = QString::fromStdString(tools::formatIssue(issue, Language::messageLanguage()));
            }
        }
        QString question = tr("Replace the tool table with the %1 tools of %2?")
                               .arg(parsed->table.size())
                               .arg(QFileInfo(path).fileName());
        if (refused > 0) {
            question += QLatin1Char(' ') + tr("%1 lines skipped, the first: %2").arg(refused).arg(skipped);
        }
        context().ask(question, [this, parsed, path](bool yes) {
            if (yes) {
                context().session().replaceToolTable(parsed->table, QFileInfo(path).fileName());
                context().notify(tr("Tool table imported from %1").arg(QFileInfo(path).fileName()));
            }
        });
    });
}

void ToolTablePage::exportTable() {
    context().askText(tr("Export the tool table to (path; relative to the machine folder):"),
                      QStringLiteral("tool-export.tbl"), [this](std::optional<QString> text) {
        if (!text || text->trimmed().isEmpty() || !shown_) {
            return;
        }
        const QString path = resolvePath(*text);
        const auto snapshot = context().snapshot();
        if (snapshot && !snapshot->programFile.isEmpty() &&
            files::outputOverGuarded(path.toStdString(), {{"", snapshot->programFile.toStdString(), false}})) {
            context().notify(tr("%1 is the loaded program: refused, nothing was written").arg(path));
            return;
        }
        if (auto error = context().folderFiles().exportToolTable(path.toStdString(), *shown_)) {
            context().notify(tr("File save failed!", "msg 907") + QStringLiteral(" ") + QString::fromStdString(error->in(Language::messageLanguage())));
            return;
        }
        context().notify(tr("Tool table exported to %1").arg(QFileInfo(path).fileName()));
    });
}

} // namespace m350::ui
