#pragma once

#include "core/tools/ToolTable.h"
#include "ui/pages/Page.h"
#include "ui/pages/PageId.h"

#include <memory>
#include <optional>

class QLabel;
class QTableWidget;

namespace m350::ui {

// 刀具表 Tool Table (a simulator page: the M350 keeps only the Z offsets, params 930-945, on its
// Probe page, which opens this one): the machine's tool table (tool.tbl) with columns T, pocket,
// Z, diameter, maximum rpm, teeth, type and comment. UP/DOWN choose the tool, LEFT/RIGHT the field,
// Enter or 修改 edits it through the prompt; 新建 adds a tool, 删除 takes one out, 对刀 touches the
// loaded tool off (its Z so that the display reads the measured work Z), 导入 / 导出 read and write
// a tool.tbl file (a path typed in the prompt, relative to the machine folder); the second row's
// 刀具寿命 (Shift+F1) opens the tool life groups (ToolLifePage), 破损监测 (Shift+F2) the breakage
// monitor (BreakageMonitorPage). ESC returns to the Probe page. Every change goes to the session,
// which saves tool.tbl.
class ToolTablePage : public Page {
    Q_OBJECT
public:
    explicit ToolTablePage(PanelContext& context, QWidget* parent = nullptr);
    QString id() const override { return PageId::tools; }
    QString title() const override;
    QVector<Softkey> softkeys() const override;
    void softkey(int number) override;
    bool key(const QString& name) override;
    void render(const PanelSnapshot& snapshot) override;
    void retranslate() override;
    QJsonObject state() const override;

    enum class Column { Tool, Pocket, Z, Diameter, Rpm, Teeth, Type, Comment };
    static constexpr int kColumns = 8;
    int rowCount() const;
    int selectedTool() const; // 0 when the table is empty
    Column selectedColumn() const { return column_; }
    QString cellText(int row, Column column) const;
    QString infoText() const;

    // How the page shows and reads the extras' type ("平底刀" / "Flat end mill", by number 1-11 too).
    static QString typeName(tools::ToolType type);

private:
    // ToolTablePageEdit.cpp
    void edit();
    void editField(const tools::ToolEntry& entry, Column column);
    void addTool();
    void removeSelected();
    void touchOff();
    void importTable();
    void exportTable();
    QString resolvePath(const QString& typed) const;
    // ToolTablePage.cpp
    void fill();
    void select(int row, Column column);
    QString columnTitle(Column column) const;
    std::optional<tools::ToolEntry> selectedEntry() const;

    QLabel* header_;
    QTableWidget* table_;
    QLabel* info_;
    QLabel* help_;
    std::shared_ptr<const tools::ToolTable> shown_;
    std::vector<tools::ToolEntry> rows_;
    Column column_ = Column::Z;
    int currentTool_ = 0;
    QString problem_; // the session's last tool.tbl save problem
};

} // namespace m350::ui
