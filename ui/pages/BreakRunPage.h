#pragma once

#include "ui/pages/Page.h"
#include "ui/pages/PageId.h"

#include <functional>

class QLabel;

namespace m350::ui {

class CompactDro;

// 断点加工 Break Run (a Monitor sub-page): the loaded file and its break points (where the last
// 暂停 stopped it; the one the machine folder keeps for 断电断点加工), and the three ways to start
// in the middle of a program: 指定行加工 asks 起始加工行号:, 断电断点加工 and 暂停断点加工 start at
// their break point, each after 文件扫描并定位成功,是否进行启动加工?. Esc goes back.
class BreakRunPage : public Page {
    Q_OBJECT
public:
    explicit BreakRunPage(PanelContext& context, QWidget* parent = nullptr);
    QString id() const override { return PageId::breakRun; }
    QString title() const override;
    QVector<Softkey> softkeys() const override;
    void softkey(int number) override;
    bool key(const QString& name) override;
    void render(const PanelSnapshot& snapshot) override;
    void retranslate() override;
    QJsonObject state() const override;

private:
    void confirm(const QString& file, int line, std::function<void()> start);
    QLabel* text_;
    CompactDro* dro_;
};

} // namespace m350::ui
