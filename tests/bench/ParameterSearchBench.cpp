// The Param page's search by number (请输入搜索的参数编号:): from a number to its tab, group and row.
#include "core/params/ParameterPages.h"

#include <benchmark/benchmark.h>

#include <variant>

namespace {

using m350::params::ParameterCatalogue;
using m350::params::ParameterPages;

const ParameterCatalogue& catalogue() {
    static const ParameterCatalogue loaded =
        std::get<ParameterCatalogue>(ParameterCatalogue::load(ParameterCatalogue::bundledPath()));
    return loaded;
}

// Every number 0-1105 in turn, listed or not, as an operator's searches would come.
void BM_ParameterSearchByNumber(benchmark::State& state) {
    ParameterPages pages(catalogue());
    int number = 0;
    for (auto _ : state) {
        benchmark::DoNotOptimize(pages.locate(number));
        number = number == 1105 ? 0 : number + 1;
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ParameterSearchByNumber);

// What the page pays once when it opens: the tabs and groups built from the 584-row catalogue.
void BM_ParameterPagesBuild(benchmark::State& state) {
    for (auto _ : state) benchmark::DoNotOptimize(ParameterPages(catalogue()));
}
BENCHMARK(BM_ParameterPagesBuild);

} // namespace
