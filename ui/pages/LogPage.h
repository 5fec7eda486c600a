#pragma once

#include "ui/pages/Page.h"
#include "ui/pages/PageId.h"

#include <QHash>

#include <cstdint>

class QLabel;
class QTableWidget;

namespace m350::ui {

// 系统日志 System Log: 时刻 / 事件明细 rows for every operation and alarm, newest first, in the
// firmware's event words; UP/DOWN select a row, ENTER shows it whole. The log lives in the machine folder (system-log.tsv) and stays bounded.
class LogPage : public Page {
    Q_OBJECT
public:
    explicit LogPage(PanelContext& context, QWidget* parent = nullptr);
    QString id() const override { return PageId::log; }
    QString title() const override;
    QVector<Softkey> softkeys() const override;
    void softkey(int number) override;
    bool key(const QString& name) override;
    void render(const PanelSnapshot& snapshot) override;
    void retranslate() override;
    QJsonObject state() const override;

    int rows() const;
    QString eventText(int row) const; // row 0 is the newest

    // The words of a logged event: "start_work" -> 开始加工 / Start working.
    static QString eventWords(const std::string& event);
    static QHash<QString, QString> eventTable();

private:
    void fill(const PanelSnapshot& snapshot);
    void fitTimeColumn(int width, int fresh);
    QTableWidget* table_;
    QLabel* problem_; // why system-log.tsv is not saved, when it is not
    const void* shown_ = nullptr; // the log list last shown (lists are replaced, never changed)
    std::uint64_t shownAdded_ = 0; // its LogTail::added()
    int shownRows_ = 0;
};

} // namespace m350::ui
