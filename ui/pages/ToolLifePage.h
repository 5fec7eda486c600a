#pragma once

#include "core/tools/ToolLifeView.h"
#include "ui/pages/Page.h"
#include "ui/pages/PageId.h"

#include <memory>

class QLabel;
class QTableWidget;

namespace m350::ui {

// 刀具寿命 Tool Life (reached by the 刀具表 page's 刀具寿命 softkey): FANUC 0i tool life management
// as the machine counts it, from the session's snapshot (core/tools/ToolLifeView). One row per
// tool, the groups in number order and their tools in use order: group, life type (count /
// minutes), life, tool, H, D, used, remaining and state, FANUC's marks: @ in use (the row is
// highlighted), # expired; a sister not yet used waits. UP/DOWN choose the tool (and so its
// group); 寿命清零 resets the group's used life after the prompt (saved to toollife.txt). On the
// M350 the manager is a simulator extra and the page says so. ESC returns to the 刀具表 page.
class ToolLifePage : public Page {
    Q_OBJECT
public:
    explicit ToolLifePage(PanelContext& context, QWidget* parent = nullptr);
    QString id() const override { return PageId::toolLife; }
    QString title() const override;
    QVector<Softkey> softkeys() const override;
    void softkey(int number) override;
    bool key(const QString& name) override;
    void render(const PanelSnapshot& snapshot) override;
    void retranslate() override;
    QJsonObject state() const override;

    enum class Column { Group, Kind, Life, Tool, H, D, Used, Remaining, State };
    static constexpr int kColumns = 9;
    int rowCount() const;
    QString cellText(int row, Column column) const;
    bool rowHighlighted(int row) const; // the sister tool in use
    int selectedGroup() const;          // 0 when there are no groups
    QString headerText() const;
    QString infoText() const;

private:
    struct Row {
        const tools::LifeGroupView* group = nullptr;
        const tools::LifeToolView* tool = nullptr;
        bool firstOfGroup = false;
    };
    void fill();
    void select(int row);
    void resetSelectedGroup();
    QString columnTitle(Column column) const;
    QString stateText(const tools::LifeToolView& tool) const;

    QLabel* header_;
    QLabel* note_;
    QTableWidget* table_;
    QLabel* info_;
    QLabel* help_;
    std::shared_ptr<const tools::LifeView> shown_;
    std::vector<Row> rows_;
    int currentRow_ = 0;
    bool tWordChangesTool_ = false;
    QString problem_; // why toollife.txt was not saved
};

} // namespace m350::ui
