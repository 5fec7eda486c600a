#pragma once

#include "ui/session/PanelSnapshot.h"

#include <QJsonObject>
#include <QString>
#include <QVector>
#include <QWidget>

namespace m350::ui {

class PanelContext;

// One screen of the panel (加工状态, MDI, IO状态, 对刀 ...). A page shows snapshots and answers the
// operator's softkeys and keys; it moves the machine only through the context's session. Adding
// a page is a local change: write a Page, give it a PageId and add it to PageTable.
class Page : public QWidget {
    Q_OBJECT
public:
    struct Softkey {
        QString text;
        bool enabled = true;
        QString tooltip; // why a key is disabled
    };

    Page(PanelContext& context, QWidget* parent = nullptr) : QWidget(parent), context_(context) {}

    virtual QString id() const = 0;    // "monitor", used by --page and the replay format
    virtual QString title() const = 0; // the page's name on the status line, translated
    // The softkeys of the current menu level: 6, or 12 for two rows (F1-F6, Shift+F1-F6).
    virtual QVector<Softkey> softkeys() const = 0;
    virtual void softkey(int number) = 0; // 1-12
    // ENTER ESC UP DOWN LEFT RIGHT; false when the page has no use for the key.
    virtual bool key(const QString& name) {
        (void)name;
        return false;
    }
    virtual bool typed(const QString& text) {
        (void)text;
        return false;
    }
    virtual void render(const PanelSnapshot& snapshot) = 0;
    // Whether render keeps something of each snapshot it is given (the MDI page's result line
    // follows the run it saw start): such a page is rendered at every snapshot even where the
    // panel may skip the snapshots nobody reads (a headless replay).
    virtual bool rendersEverySnapshot() const { return false; }
    // Whether what the page shows after a key depends on the height and width the layout gave it
    // then, not only on its state (a text editor scrolled to its cursor, a machine view fitted to
    // a path): a headless replay lays such a page out before each action on it. A page of
    // PanelTables need not: a table shows the current row's page whatever way the cursor came.
    virtual bool readsLayout() const { return false; }
    // The operator came to the page (its key, a softkey, a replay's "page").
    virtual void opened() {}
    // Whether the page draws the machine (snapshots then carry its scene).
    virtual bool drawsMachine() const { return false; }
    virtual void retranslate() {}
    virtual QJsonObject state() const { return {}; } // page-specific part of --state

signals:
    void softkeysChanged();
    void navigate(const QString& pageId); // a softkey that opens another page (对刀, MDI)
    void editSource(const QString& file, int line); // opens a file in the Program page's editor at a line

protected:
    PanelContext& context() const { return context_; }
    void changeEvent(QEvent* event) override;

private:
    PanelContext& context_;
};

} // namespace m350::ui
