#include "ui/pages/MdiPage.h"

#include "ui/i18n/AlarmText.h"
#include "ui/pages/CompactDro.h"
#include "ui/pages/MdiLines.h"
#include "ui/pages/PanelContext.h"
#include "ui/widgets/TextSizeDelegate.h"
#include "ui/widgets/WrappedLabel.h"

#include <QJsonArray>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QVBoxLayout>

namespace m350::ui {

using Run = controller::PanelStatus::Run;

MdiPage::MdiPage(PanelContext& context, QWidget* parent) : Page(context, parent) {
    setObjectName("mdiPage");
    auto* column = new QVBoxLayout(this);
    column->setContentsMargins(4, 4, 4, 4);
    list_ = new QListWidget(this);
    list_->setObjectName("mdiLines");
    list_->setFocusPolicy(Qt::NoFocus);
    new TextSizeDelegate(list_);
    editor_ = new QLineEdit(this);
    editor_->setObjectName("mdiEditor");
    editor_->setFocusPolicy(Qt::NoFocus); // keys reach it through the dispatcher
    editor_->hide();
    result_ = new WrappedLabel(this);
    result_->setObjectName("mdiResult");
    help_ = new WrappedLabel(this);
    help_->setObjectName("pageHelp");
    list_->setMaximumHeight(6 * 26 + 8);
    dro_ = new CompactDro(this);
    column->addWidget(list_);
    column->addWidget(editor_);
    column->addWidget(result_);
    column->addWidget(dro_);
    column->addStretch(1);
    column->addWidget(help_);
    QString error;
    lines_ = MdiLines::load(context.machineFolder(), &error);
    if (!error.isEmpty()) {
        context.notify(error);
    }
    refreshList();
    retranslate();
}

QString MdiPage::title() const { return tr("MDI", "msg 11"); }

void MdiPage::retranslate() {
    help_->setText(tr("[Knob]Move the cursor,[Enter]Edit current line,[Execute]Execute current line.", "msg 962"));
}

QVector<Page::Softkey> MdiPage::softkeys() const {
    return {{tr("Execute(1)", "msg 372"), true, {}}, {tr("Execute(2)", "msg 373"), true, {}},
            {tr("Execute(3)", "msg 374"), true, {}}, {tr("Execute(4)", "msg 375"), true, {}},
            {tr("Execute(5)", "msg 376"), true, {}}, {tr("Execute(6)", "msg 377"), true, {}}};
}

void MdiPage::softkey(int number) {
    if (number >= 1 && number <= MdiLines::kCount) {
        if (editing()) {
            commitEdit();
        }
        run(number);
    }
}

void MdiPage::run(int line) {
    const QString text = lines_[line - 1].trimmed();
    if (text.isEmpty()) {
        context().notify(tr("MDI line %1 is empty").arg(line));
        return;
    }
    running_ = line;
    started_ = false;
    context().session().runMdiPageLine(text);
}

bool MdiPage::key(const QString& name) {
    if (editing()) {
        if (name == QLatin1String("ENTER")) {
            commitEdit();
        } else if (name == QLatin1String("ESC")) {
            cancelEdit();
        } else if (name == QLatin1String("BACKSPACE")) {
            editor_->backspace();
        } else if (name == QLatin1String("LEFT")) {
            editor_->cursorBackward(false);
        } else if (name == QLatin1String("RIGHT")) {
            editor_->cursorForward(false);
        } else {
            return false;
        }
        return true;
    }
    if (name == QLatin1String("UP") || name == QLatin1String("DOWN")) {
        int step = name == QLatin1String("UP") ? -1 : 1;
        selected_ = (selected_ + step + MdiLines::kCount) % MdiLines::kCount;
        refreshList();
        return true;
    }
    if (name == QLatin1String("ENTER")) {
        startEdit(true);
        return true;
    }
    return false;
}

bool MdiPage::typed(const QString& text) {
    if (!editing()) {
        startEdit(false); // typing over a line replaces it
    }
    editor_->insert(text);
    return true;
}

bool MdiPage::editing() const { return !editor_->isHidden(); }

void MdiPage::startEdit(bool keepText) {
    editor_->setText(keepText ? lines_[selected_] : QString());
    editor_->setPlaceholderText(QStringLiteral("%1:").arg(selected_ + 1));
    editor_->show();
}

void MdiPage::commitEdit() {
    QStringList edited = lines_;
    edited[selected_] = editor_->text().trimmed();
    QString error;
    if (!MdiLines::save(context().machineFolder(), edited, &error)) {
        context().notify(error); // the line stays in the editor: nothing typed is lost
        return;
    }
    lines_ = edited;
    editor_->hide();
    refreshList();
}

void MdiPage::cancelEdit() {
    editor_->hide();
    refreshList();
}

void MdiPage::refreshList() {
    list_->clear();
    for (int i = 0; i < lines_.size(); ++i) {
        list_->addItem(QStringLiteral("%1: %2").arg(i + 1).arg(lines_[i]));
    }
    list_->setCurrentRow(selected_);
}

void MdiPage::render(const PanelSnapshot& snapshot) {
    const controller::PanelStatus& s = snapshot.status;
    dro_->render(snapshot);
    if (running_ == 0) {
        result_->clear();
        return;
    }
    QString head = tr("Execute(%1)").arg(running_) + QStringLiteral(" ") + lines_[running_ - 1] + QStringLiteral(": ");
    if (!snapshot.lastError.isEmpty()) {
        result_->setText(head + snapshot.lastError);
        return;
    }
    if (!s.mdi) {
        return;
    }
    switch (s.run) {
    case Run::Running:
    case Run::Hold: started_ = true; result_->setText(head + tr("BUSY", "msg 21")); break;
    case Run::Finished: result_->setText(head + tr("done")); break;
    case Run::Alarm:
    case Run::EStop:
        result_->setText(head + (s.alarm ? AlarmText::message(*s.alarm) : tr("ALARM", "msg 24")));
        break;
    case Run::Idle: break;
    }
}

QString MdiPage::resultText() const { return result_->text(); }

QJsonObject MdiPage::state() const {
    QJsonArray lines;
    for (const QString& line : lines_) {
        lines.append(line);
    }
    return {{"mdi_lines", lines}, {"mdi_selected", selected_ + 1}, {"mdi_result", result_->text()}};
}

} // namespace m350::ui
