#pragma once

#include "core/params/ParameterCatalogue.h"

#include <QCoreApplication>
#include <QString>

#include <string>

namespace m350::ui {

// The words the Param page shows of a parameter, in the panel's language: its group's title, its
// value (a selection by its option's name), its range, a name in Chinese or English. Its words
// keep the Param page's translation context.
class ParameterText {
    Q_DECLARE_TR_FUNCTIONS(m350::ui::ParamPage)
public:
    static QString groupTitle(int group);
    static QString value(const params::ParameterInfo& info, double value);
    static QString range(const params::ParameterInfo& info);
    // `zh` when the panel speaks Chinese and it has one, else `en`.
    static QString localName(const std::string& zh, const std::string& en, bool chinese);
    static QString localName(const std::string& zh, const std::string& en);
};

} // namespace m350::ui
