#include "app/hmi/Refusal.h"

#include <cstdio>

namespace m350::hmi {

int refuse(const QString& message, int status) {
    std::fprintf(stderr, "m350-hmi: %s\n", qPrintable(message));
    return status;
}

} // namespace m350::hmi
