#pragma once

#include <QLatin1StringView>
#include <QList>
#include <QStringList>

class QWidget;

namespace m350::ui {

class Page;
class PanelContext;

// Every page of the panel once: its id and how it is made, in the order the panel registers them.
// MainWindow builds its pages from it; --page and the replay format accept exactly its ids.
class PageTable {
public:
    struct Entry {
        QLatin1StringView id;
        Page* (*make)(PanelContext& context, QWidget* parent);
    };
    static const QList<Entry>& entries();
    static const QStringList& ids();
};

} // namespace m350::ui
