#pragma once

#include "ui/pages/Page.h"
#include "ui/pages/PageId.h"

class QLabel;

namespace m350::ui {

// 加工统计 Work Record (a Monitor sub-page): the current program, pieces, time per piece, total
// time, when it began; 清除加工记录 clears it after the panel's question, 导出到U盘 writes
// PROCES_MSG.txt (here: into the machine folder, the simulator's "U disk"). Esc goes back.
class RecordPage : public Page {
    Q_OBJECT
public:
    explicit RecordPage(PanelContext& context, QWidget* parent = nullptr);
    QString id() const override { return PageId::record; }
    QString title() const override;
    QVector<Softkey> softkeys() const override;
    void softkey(int number) override;
    bool key(const QString& name) override;
    void render(const PanelSnapshot& snapshot) override;
    void retranslate() override;
    QJsonObject state() const override;

    QString recordText() const;

private:
    void exportRecord();
    QLabel* record_;
};

} // namespace m350::ui
