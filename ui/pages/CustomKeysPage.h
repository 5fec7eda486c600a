#pragma once

#include "ui/pages/Page.h"
#include "ui/pages/PageId.h"

#include <array>

class QLabel;
class QPushButton;

namespace m350::ui {

// 定制功能 Manual (the Monitor's second row): the add-on keypad's FUNC K01-K14 (扩展按键01-14).
// Arrows choose a key, Enter or F1 presses it: #1996 = M250-M263 and the machine folder's
// ext_button.nc (`M#1996`) runs, or that M code as MDI when the folder has none. Esc goes back.
class CustomKeysPage : public Page {
    Q_OBJECT
public:
    static constexpr int kKeys = 14;

    explicit CustomKeysPage(PanelContext& context, QWidget* parent = nullptr);
    QString id() const override { return PageId::custom; }
    QString title() const override;
    QVector<Softkey> softkeys() const override;
    void softkey(int number) override;
    bool key(const QString& name) override;
    void render(const PanelSnapshot& snapshot) override;
    void retranslate() override;
    QJsonObject state() const override;

private:
    void select(int key);
    void press();
    bool folderHasHook() const;
    void updateRuns();

    int selected_ = 1;
    std::array<QPushButton*, kKeys> keys_{};
    QLabel* runs_;
};

} // namespace m350::ui
