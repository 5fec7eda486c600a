#pragma once

#include "ui/pages/Page.h"
#include "ui/pages/PageId.h"

#include <array>

class QLabel;

namespace m350::ui {
class ProgramWindow;
}

namespace m350::ui {

// 加工状态 Monitor: machine (机械坐标) and work (工件坐标) coordinates of every configured axis with
// its homed marker, the work system, the overrides, feed, spindle, tool, counters, run time and
// the modal line, and the program window (ProgramWindow) following the run. Softkeys as on the panel (two rows); 回机械原点, 回工件原点 and 清零 open their
// own rows (per axis and all), Esc goes back.
class MonitorPage : public Page {
    Q_OBJECT
public:
    explicit MonitorPage(PanelContext& context, QWidget* parent = nullptr);
    QString id() const override { return PageId::monitor; }
    QString title() const override;
    QVector<Softkey> softkeys() const override;
    void softkey(int number) override;
    bool key(const QString& name) override;
    void render(const PanelSnapshot& snapshot) override;
    void retranslate() override;
    QJsonObject state() const override;

    enum class Menu { Main, GoHome, GoWorkZero, Clear };
    Menu menu() const { return menu_; }
    QString machineText(int axis) const; // what the DRO shows, for tests
    QString workText(int axis) const;
    QString axisText(int axis) const; // the DRO row's name ("A ○") and unit ("deg"), for tests
    QString unitText(int axis) const;
    bool axisVisible(int axis) const;
    QString infoText(const QString& name) const; // "tool", "feed", "spindle", "fro" ...
    const ProgramWindow* programWindow() const { return program_; }

private:
    void openMenu(Menu menu);
    void axisCommand(int number);
    QLabel* infoLabel(const QString& name);
    std::array<QLabel*, 5> axisName_{};
    std::array<QLabel*, 5> machine_{};
    std::array<QLabel*, 5> work_{};
    std::array<QLabel*, 5> unit_{};
    QLabel* axisHeader_;
    QLabel* machineHeader_;
    QLabel* workHeader_;
    QMap<QString, QLabel*> captions_;
    QMap<QString, QLabel*> values_;
    QLabel* modal_;
    ProgramWindow* program_ = nullptr;
    Menu menu_ = Menu::Main;
    std::array<bool, 5> shown_{true, true, true, false, false};
    QString names_; // the axes' names the softkeys were made with
};

} // namespace m350::ui
