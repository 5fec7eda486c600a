#include "ui/pages/PageTable.h"

#include "ui/pages/BreakRunPage.h"
#include "ui/pages/BreakageMonitorPage.h"
#include "ui/pages/CoordPage.h"
#include "ui/pages/CustomKeysPage.h"
#include "ui/pages/GraphicsPage.h"
#include "ui/pages/IoPage.h"
#include "ui/pages/LogPage.h"
#include "ui/pages/MdiPage.h"
#include "ui/pages/MiddlePage.h"
#include "ui/pages/MonitorPage.h"
#include "ui/pages/PageId.h"
#include "ui/pages/ParamPage.h"
#include "ui/pages/ProbePage.h"
#include "ui/pages/ProgramPage.h"
#include "ui/pages/RecordPage.h"
#include "ui/pages/SystemPage.h"
#include "ui/pages/ToolLifePage.h"
#include "ui/pages/ToolTablePage.h"

namespace m350::ui {

namespace {

template <class PageType> Page* make(PanelContext& context, QWidget* parent) {
    return new PageType(context, parent);
}

} // namespace

const QList<PageTable::Entry>& PageTable::entries() {
    static const QList<Entry> pages{
        {PageId::monitor, make<MonitorPage>},   {PageId::mdi, make<MdiPage>},
        {PageId::io, make<IoPage>},             {PageId::probe, make<ProbePage>},
        {PageId::program, make<ProgramPage>},   {PageId::param, make<ParamPage>},
        {PageId::log, make<LogPage>},           {PageId::system, make<SystemPage>},
        {PageId::coord, make<CoordPage>},       {PageId::middle, make<MiddlePage>},
        {PageId::record, make<RecordPage>},     {PageId::breakRun, make<BreakRunPage>},
        {PageId::tools, make<ToolTablePage>},   {PageId::toolLife, make<ToolLifePage>},
        {PageId::breakage, make<BreakageMonitorPage>}, {PageId::custom, make<CustomKeysPage>},
        {PageId::graphics, make<GraphicsPage>},
    };
    return pages;
}

const QStringList& PageTable::ids() {
    static const QStringList ids = [] {
        QStringList all;
        for (const Entry& entry : entries()) {
            all << entry.id;
        }
        return all;
    }();
    return ids;
}

} // namespace m350::ui
