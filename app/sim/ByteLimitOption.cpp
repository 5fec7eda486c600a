#include "app/sim/ByteLimitOption.h"

#include <charconv>

namespace m350::sim {

namespace {

// 1024 -> "1K", 1536 -> "1536": the largest suffix that divides evenly, for a readable bound.
std::string readableBytes(std::uint64_t bytes) {
    const char* const suffixes[] = {"", "K", "M", "G", "T"};
    std::size_t unit = 0;
    while (unit + 1 < std::size(suffixes) && bytes != 0 && bytes % 1024 == 0) {
        bytes /= 1024;
        ++unit;
    }
    return std::to_string(bytes) + suffixes[unit];
}

} // namespace

CLI::Option* addByteLimitOption(CLI::App& command, const std::string& name, std::uint64_t& bytes, std::uint64_t most,
                                const std::string& description) {
    // AsSizeValue has turned the text into a plain count by now (or refused it).
    auto inRange = [most](std::string& value) -> std::string {
        std::uint64_t count = 0;
        const char* end = value.data() + value.size();
        const auto [stop, error] = std::from_chars(value.data(), end, count);
        if (error != std::errc() || stop != end || count < 1 || count > most) {
            return value + " bytes: the limit runs from 1 byte to " + readableBytes(most) +
                   " (a count of bytes, with K, M or G for 1024, 1024^2, 1024^3)";
        }
        return {};
    };
    static const CLI::AsSizeValue kSizes(false); // its unit table is built once, not per option
    return command.add_option(name, bytes, description)
        ->transform(kSizes)
        ->check(CLI::Validator(inRange, "SIZE"));
}

} // namespace m350::sim
