#pragma once

#include "ui/pages/Page.h"
#include "ui/pages/PageId.h"

#include <QMap>

class QLabel;

namespace m350::ui {

// 系统管理 System Info: 系统名称, 系统软件版本 (the project's version), the machine and its folder,
// the parameter and program counts, the user level. 密码设置 changes the current level's password;
// the other firmware keys (软件注册, 系统升级, 系统维护, 系统备份) are shown disabled, each saying why.
class SystemPage : public Page {
    Q_OBJECT
public:
    explicit SystemPage(PanelContext& context, QWidget* parent = nullptr);
    QString id() const override { return PageId::system; }
    QString title() const override;
    QVector<Softkey> softkeys() const override;
    void softkey(int number) override;
    void render(const PanelSnapshot& snapshot) override;
    void retranslate() override;
    QJsonObject state() const override;

    QString fieldText(const QString& name) const; // "name" "version" "machine" "folder" "params" "programs" "level"

protected:
    void opened() override;

private:
    void countPrograms();
    QMap<QString, QLabel*> captions_;
    QMap<QString, QLabel*> fields_;
    int programs_ = 0;
    int catalogued_ = 0;
    int listed_ = 0;
};

} // namespace m350::ui
