#include "core/controller/ProgramStop.h"

namespace m350::controller {

std::string ProgramStop::bilingualWhat(const std::string& what) {
    if (what == "M00 program stop") return bilingual(what, "M00 程序停止");
    if (what == "M01 optional stop") return bilingual(what, "M01 选择停止");
    if (what == "G04 P-1 waits for START") return bilingual(what, "G04 P-1 等待循环启动");
    return what;
}

void ProgramStop::stoppedBy(const std::string& what, const TraceSource& where) {
    const std::string place = " (" + where.file + ":" + std::to_string(where.line) + ")";
    text_ = what + place;
    startWords_ = message("notice_start_after_stop",
                          {bilingual(text_, argumentIn(bilingualWhat(what), MessageLanguage::Chinese) + place)});
}

void ProgramStop::singleBlock(const TraceSource& where) {
    const std::string place = where.file + ":" + std::to_string(where.line);
    text_ = "single block stop (" + place + ")";
    startWords_ = message("notice_start_after_stop", {bilingual(text_, "单段停止 (" + place + ")")});
}

} // namespace m350::controller
