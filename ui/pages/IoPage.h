#pragma once

#include "ui/pages/Page.h"
#include "ui/pages/PageId.h"
#include "ui/session/MachineSession.h"

#include <QVector>

#include <array>

class QLabel;
class QTableWidget;

namespace m350::ui {

// IO状态: the port table (lamp, port name, enable, pin, polarity) of every function the machine
// folder wires, and the IN01-IN24 / OUT01-OUT21 lamps, live. UP/DOWN select a port; F1 输出开,
// F2 输出关 switch the selected output, F4 修改极性 flips its active level. The second row is the
// simulator's extra, marked as such: force the selected input stuck at 0 or 1, slow, bouncing, or
// clear the fault; the sensor-wait watchdog then names it.
class IoPage : public Page {
    Q_OBJECT
public:
    explicit IoPage(PanelContext& context, QWidget* parent = nullptr);
    QString id() const override { return PageId::io; }
    QString title() const override;
    QVector<Softkey> softkeys() const override;
    void softkey(int number) override;
    bool key(const QString& name) override;
    void render(const PanelSnapshot& snapshot) override;
    void retranslate() override;
    QJsonObject state() const override;

    bool inputLit(int pin) const;
    bool outputLit(int pin) const;
    int selectedFunction() const; // the parameter of the selected row, 0 when none
    bool selectFunction(int parameter);
    QString watchText() const;

private:
    struct Row {
        int parameter = 0;
        bool input = true;
    };
    void rebuildTable(const PanelSnapshot& snapshot);
    void fillRow(int row, const PanelSnapshot& snapshot);
    void switchOutput(bool on);
    void pressSelected();
    void forceSelected(MachineSession::Fault fault, int level);
    QTableWidget* table_;
    std::array<QLabel*, 24> inputs_{};
    std::array<QLabel*, 21> outputs_{};
    QLabel* inputsTitle_;
    QLabel* outputsTitle_;
    QLabel* watch_;
    QVector<Row> rows_;
    QVector<int> wiring_; // pins of every function, to notice a change of the table
};

} // namespace m350::ui
