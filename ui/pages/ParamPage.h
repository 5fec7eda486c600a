#pragma once

#include "core/params/ParameterCatalogue.h"
#include "core/params/ParameterPages.h"
#include "ui/pages/Page.h"
#include "ui/pages/PageId.h"

#include <optional>
#include <vector>

class QLabel;
class QTableWidget;

namespace m350::ui {

// 参数管理 Param: the parameters by the firmware's groups on two tabs, 厂商参数(N) and 用户参数(O)
// (N / O typed switch them), columns 序号 / 说明 / 数值 / 单位, and beside the table what the panel
// shows of the selected one: 修改权限, 参数类别, 参数说明, 生效时间, 设定范围 (the options of a select).
// UP/DOWN move, LEFT/RIGHT or 参数分类 change the group, Enter edits through the prompt: the level
// must suffice (ParameterPages), a value outside the range is refused with [%d]号参数输入的数据非法!
// and changes nothing; an accepted one goes to the session, which saves params.toml. 搜索 finds a
// number, 参数备份 / 参数恢复 write and read the machine folder's params-backup.toml, #50-#499 shows
// and edits those variables (ESC or the key again returns).
class ParamPage : public Page {
    Q_OBJECT
public:
    explicit ParamPage(PanelContext& context, QWidget* parent = nullptr);
    QString id() const override { return PageId::param; }
    QString title() const override;
    QVector<Softkey> softkeys() const override;
    void softkey(int number) override;
    bool key(const QString& name) override;
    bool typed(const QString& text) override;
    void render(const PanelSnapshot& snapshot) override;
    void retranslate() override;
    QJsonObject state() const override;

    using Tab = params::ParameterPages::Tab;
    Tab tab() const;
    bool variablesShown() const { return variables_; }
    int selectedNumber() const; // the parameter (or #variable) of the selected row, -1 when none
    bool select(int number);    // the parameter's tab and group, then its row; false when not listed
    QString valueText(int row) const;
    QString infoText() const; // the side panel, one line per field

private:
    // ParamPageEdit.cpp
    void edit();
    void editParameter(int number);
    void editVariable(int number);
    void search();
    void backup();
    void restore();
    // ParamPage.cpp
    void showCategory(std::size_t category);
    void showCaptions();
    void showTab(Tab tab);
    void showVariables(bool on);
    void fillValues(const PanelSnapshot& snapshot);
    void fillInfo();

    std::optional<params::ParameterCatalogue> catalogue_;
    std::optional<params::ParameterPages> pages_;
    QString catalogueError_;
    std::size_t category_ = 0;
    std::vector<int> unitWidths_; // by group: its unit column's width, 0 until measured
    bool variables_ = false;
    QLabel* tabs_;
    QLabel* group_;
    QTableWidget* table_;
    QLabel* info_;
    SnapshotPtr shown_; // the snapshot the values come from
    // What the info lines below the table were written for: the same again writes nothing (their
    // words cost a dozen translations, at every snapshot and every cursor move).
    struct InfoFor {
        int number = -1;
        bool variables = false;
        params::UserLevel level = params::UserLevel::Guest;
        std::size_t category = 0;
        friend bool operator==(const InfoFor&, const InfoFor&) = default;
    };
    std::optional<InfoFor> infoFor_;
};

} // namespace m350::ui
