#pragma once

#include <QLatin1StringView>

namespace m350::ui {

// The ids of the panel's pages: what --page, the replay format's "page", --state's "page" and a
// page's navigate() call them. PageTable registers one page for each.
struct PageId {
    static constexpr QLatin1StringView monitor{"monitor"};
    static constexpr QLatin1StringView mdi{"mdi"};
    static constexpr QLatin1StringView io{"io"};
    static constexpr QLatin1StringView probe{"probe"};
    static constexpr QLatin1StringView program{"program"};
    static constexpr QLatin1StringView param{"param"};
    static constexpr QLatin1StringView log{"log"};
    static constexpr QLatin1StringView system{"system"};
    static constexpr QLatin1StringView coord{"coord"};
    static constexpr QLatin1StringView middle{"middle"};
    static constexpr QLatin1StringView record{"record"};
    static constexpr QLatin1StringView breakRun{"breakrun"};
    static constexpr QLatin1StringView tools{"tools"};
    static constexpr QLatin1StringView toolLife{"toollife"};
    static constexpr QLatin1StringView breakage{"breakage"};
    static constexpr QLatin1StringView custom{"custom"};
    static constexpr QLatin1StringView graphics{"graphics"};
};

} // namespace m350::ui
