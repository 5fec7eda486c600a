// The Param page's 搜索 as the operator sees it: from a number to its tab and group shown, the
// table filled with that group's rows and values, and the row selected. Each search lands in
// another group (Process, Tools' 144 rows, the input ports, Machine), so the table is refilled.
#include "core/config/MachineConfig.h"
#include "ui/pages/PanelContext.h"
#include "ui/pages/ParamPage.h"
#include "ui/session/MachineSession.h"

#include <QCoreApplication>

#include <benchmark/benchmark.h>

#include <variant>

namespace {

void BM_ParamPageSearch(benchmark::State& state) {
    auto loaded = m350::config::loadMachineFolder(m350::config::bundledMachinesDirectory() + "/" +
                                                  m350::config::kDefaultMachine);
    m350::ui::MachineSession::Options options;
    options.clock = m350::ui::MachineSession::Clock::Manual;
    m350::ui::MachineSession session(std::get<m350::config::MachineConfig>(std::move(loaded)), options);
    session.sync();
    QCoreApplication::processEvents(); // the first snapshot: the values the table shows
    m350::ui::PanelContext context(session, {});
    m350::ui::ParamPage page(context);
    const int numbers[] = {61, 930, 545, 1};
    std::size_t next = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(page.select(numbers[next]));
        next = (next + 1) % std::size(numbers);
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ParamPageSearch)->Unit(benchmark::kMicrosecond);

} // namespace
