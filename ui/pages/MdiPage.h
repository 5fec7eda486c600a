#pragma once

#include "ui/pages/Page.h"
#include "ui/pages/PageId.h"

#include <QStringList>

class QLabel;
class QLineEdit;
class QListWidget;

namespace m350::ui {
class CompactDro;
}

namespace m350::ui {

// MDI: six numbered lines kept in the machine folder. UP/DOWN move the selection bar, typing or
// Enter edits the selected line (Enter again keeps it, Esc drops the edit), F1-F6 run line 1-6
// (执行(1)..执行(6)); the line running and its result or alarm show under the list.
class MdiPage : public Page {
    Q_OBJECT
public:
    explicit MdiPage(PanelContext& context, QWidget* parent = nullptr);
    QString id() const override { return PageId::mdi; }
    QString title() const override;
    QVector<Softkey> softkeys() const override;
    void softkey(int number) override;
    bool key(const QString& name) override;
    bool typed(const QString& text) override;
    void render(const PanelSnapshot& snapshot) override;
    bool rendersEverySnapshot() const override { return true; }
    void retranslate() override;
    QJsonObject state() const override;

    const QStringList& lines() const { return lines_; }
    int selected() const { return selected_; }
    bool editing() const;
    QString resultText() const;

private:
    void startEdit(bool keepText);
    void commitEdit();
    void cancelEdit();
    void refreshList();
    void run(int line);
    QListWidget* list_;
    CompactDro* dro_;
    QLineEdit* editor_;
    QLabel* result_;
    QLabel* help_;
    QStringList lines_;
    int selected_ = 0;
    int running_ = 0; // 1-6 the line last started, 0 none
    bool started_ = false;
};

} // namespace m350::ui
