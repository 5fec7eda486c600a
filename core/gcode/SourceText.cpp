#include "core/gcode/SourceText.h"

#include "core/gcode/LineSplitter.h"
#include "core/gcode/MappedFile.h"

#include <iconv.h>

#if defined(__unix__)
#define M350_HAVE_MMAP 1
#include "core/files/FileDescriptor.h"
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#else
#define M350_HAVE_MMAP 0
#endif

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>
#include <optional>
#include <system_error>

namespace m350::gcode {
namespace {

constexpr std::string_view kUtf8Bom = "\xEF\xBB\xBF";

// Offset of the first byte that does not start a well-formed UTF-8 sequence
// (Unicode table 3-7: rejects overlongs, surrogates and code points > U+10FFFF).
std::optional<std::size_t> firstInvalidUtf8(std::string_view s) {
    std::size_t i = 0;
    while (i < s.size()) {
        // Programs are mostly ASCII: skip it 32, then eight bytes at a time.
        constexpr std::uint64_t kHighBits = 0x8080808080808080ull;
        std::uint64_t chunks[4] = {};
        while (s.size() - i >= sizeof chunks && (std::memcpy(chunks, s.data() + i, sizeof chunks),
                                                 (chunks[0] | chunks[1] | chunks[2] | chunks[3]) & kHighBits) == 0) {
            i += sizeof chunks;
        }
        std::uint64_t chunk = 0;
        while (s.size() - i >= sizeof chunk && (std::memcpy(&chunk, s.data() + i, sizeof chunk), chunk & kHighBits) == 0) {
            i += sizeof chunk;
        }
        if (i >= s.size()) {
            break;
        }
        const auto lead = static_cast<unsigned char>(s[i]);
        if (lead < 0x80) {
            ++i;
            continue;
        }
        std::size_t len = 0;
        unsigned char lo = 0x80;
        unsigned char hi = 0xBF;
        if (lead >= 0xC2 && lead <= 0xDF) {
            len = 2;
        } else if (lead >= 0xE0 && lead <= 0xEF) {
            len = 3;
            if (lead == 0xE0) lo = 0xA0;
            if (lead == 0xED) hi = 0x9F;
        } else if (lead >= 0xF0 && lead <= 0xF4) {
            len = 4;
            if (lead == 0xF0) lo = 0x90;
            if (lead == 0xF4) hi = 0x8F;
        } else {
            return i;
        }
        if (s.size() - i < len) return i;
        for (std::size_t k = 1; k < len; ++k) {
            const auto c = static_cast<unsigned char>(s[i + k]);
            if (c < lo || c > hi) return i;
            lo = 0x80;
            hi = 0xBF;
        }
        i += len;
    }
    return std::nullopt;
}

class Iconv {
public:
    Iconv(const char* to, const char* from) : cd_(iconv_open(to, from)) {}
    ~Iconv() {
        if (ok()) iconv_close(cd_);
    }
    Iconv(const Iconv&) = delete;
    Iconv& operator=(const Iconv&) = delete;

    bool ok() const { return cd_ != reinterpret_cast<iconv_t>(static_cast<std::intptr_t>(-1)); }
    iconv_t get() const { return cd_; }

private:
    iconv_t cd_;
};

// The decoded UTF-8 text, or the offset of the first byte iconv rejected.
std::variant<std::string, std::size_t> decodeGbk(const Iconv& cd, std::string_view bytes) {
    // A GB18030 sequence never grows by more than 1.5x in UTF-8, so 2x never hits E2BIG.
    std::string out(bytes.size() * 2, '\0');
    // iconv's input parameter is char** for historical reasons; it does not write through it.
    char* in = const_cast<char*>(bytes.data());
    std::size_t inLeft = bytes.size();
    char* outPtr = out.data();
    std::size_t outLeft = out.size();
    if (iconv(cd.get(), &in, &inLeft, &outPtr, &outLeft) == static_cast<std::size_t>(-1)) {
        return static_cast<std::size_t>(in - bytes.data());
    }
    out.resize(out.size() - outLeft);
    return out;
}

// Lines end as the parser ends them (LF, CRLF or CR alone), so the line agrees with its diagnostics.
std::pair<std::uint32_t, std::uint32_t> lineAndColumn(std::string_view bytes, std::size_t offset) {
    const std::string_view before = bytes.substr(0, offset);
    LineSplitter lines(before);
    std::string_view line;
    std::size_t count = 0;
    std::size_t lineStart = 0;
    while (lines.next(line)) {
        ++count;
        lineStart = lines.lineStart(line);
    }
    return {static_cast<std::uint32_t>(count), static_cast<std::uint32_t>(offset - lineStart + 1)};
}

// A UTF-16 file (Windows Notepad's "Unicode") is neither UTF-8 nor GBK, but saying so helps more
// than a bad byte at column 1: a byte-order mark, or ASCII text with every other byte 0.
bool looksUtf16(std::string_view bytes) {
    if (bytes.starts_with("\xFF\xFE") || bytes.starts_with("\xFE\xFF")) {
        return true;
    }
    const std::size_t sample = std::min<std::size_t>(bytes.size(), 256);
    std::size_t zeros = 0;
    for (std::size_t i = 0; i < sample; ++i) {
        zeros += bytes[i] == '\0';
    }
    return sample >= 4 && zeros * 3 >= sample;
}

std::string errnoMessage(int err) { return std::error_code(err, std::generic_category()).message(); }

// The system's words for errno in both languages (the common ones in Chinese; the others as the
// system says them).
std::string errnoWords(int err) {
    const char* chinese = err == ENOENT    ? "没有该文件或目录"
                          : err == EACCES  ? "权限不足"
                          : err == EISDIR  ? "是一个目录"
                          : err == ENOTDIR ? "路径中有一项不是目录"
                          : err == ELOOP   ? "符号链接层数过多"
                          : err == EMFILE  ? "打开的文件过多"
                          : err == EIO     ? "输入/输出错误"
                          : err == ENOMEM  ? "内存不足"
                                           : nullptr;
    return chinese ? bilingual(errnoMessage(err), chinese) : errnoMessage(err);
}

struct FileCloser {
    void operator()(std::FILE* f) const { std::fclose(f); }
};

}  // namespace

std::string_view encodingName(TextEncoding encoding) {
    return encoding == TextEncoding::Gbk ? "GBK" : "UTF-8";
}

namespace {

// The offset of the first bad UTF-8 byte. A mapped file too large to be read in at once is checked
// a window at a time, and the pages of each window are let go once checked: a 1 GB program must not
// stay in memory for this. A smaller one keeps its pages for the parser, which reads them next.
std::optional<std::size_t> firstInvalidUtf8(std::string_view body, const MappedFile* mapping) {
    if (mapping == nullptr || mapping->bytes().size() <= MappedFile::kPopulateBytes) {
        return firstInvalidUtf8(body);
    }
    constexpr std::size_t kWindow = std::size_t{16} << 20;
    const std::size_t bodyOffset = static_cast<std::size_t>(body.data() - mapping->bytes().data());
    std::size_t at = 0;
    while (at < body.size()) {
        std::size_t end = std::min(body.size(), at + kWindow);
        // a window ends before a lead byte, never inside a sequence
        while (end < body.size() && end > at && (static_cast<unsigned char>(body[end]) & 0xC0) == 0x80) {
            --end;
        }
        if (end == at) {
            end = std::min(body.size(), at + kWindow);
        }
        if (auto bad = firstInvalidUtf8(body.substr(at, end - at))) {
            return at + *bad;
        }
        mapping->release(bodyOffset + at, bodyOffset + end);
        at = end;
    }
    return std::nullopt;
}

// Decodes `bytes`, which `owner` keeps alive: valid UTF-8 becomes the text as it lies.
std::variant<SourceText, SourceReadError> decodeOwned(std::string path, std::string_view bytes,
                                                      std::shared_ptr<const void> owner,
                                                      std::shared_ptr<const MappedFile> mapping = nullptr) {
    if (looksUtf16(bytes)) { // its NUL bytes would pass as UTF-8
        return SourceReadError::of(std::move(path), message("file_utf16"), 1, 1);
    }
    const std::size_t bomSize = bytes.starts_with(kUtf8Bom) ? kUtf8Bom.size() : 0;
    const std::string_view body = bytes.substr(bomSize);
    const auto utf8Bad = firstInvalidUtf8(body, mapping.get());
    if (!utf8Bad) {
        return SourceText{std::move(path), body, TextEncoding::Utf8, std::move(owner), std::move(mapping)};
    }
    if (bytes.size() > kMostSourceBytes) {
        const auto [line, column] = lineAndColumn(bytes, bomSize + *utf8Bad);
        return SourceReadError::of(std::move(path),
                                   message("file_big_not_utf8", {std::to_string(bytes.size() / (1024 * 1024)),
                                                                 std::to_string(line), std::to_string(column),
                                                                 std::to_string(kMostSourceBytes / (1024 * 1024))}),
                                   line, column);
    }

    const Iconv cd("UTF-8", "GB18030");
    if (!cd.ok()) {
        return SourceReadError::of(std::move(path), message("file_no_gbk", {errnoWords(errno)}));
    }
    auto gbk = decodeGbk(cd, body);
    if (auto* text = std::get_if<std::string>(&gbk)) {
        auto decoded = std::make_shared<const std::string>(std::move(*text));
        std::string_view view = *decoded;
        return SourceText{std::move(path), view, TextEncoding::Gbk, std::move(decoded), nullptr};
    }

    // The encoding that got further is most likely the intended one, so its
    // failure point is the byte worth showing to the user.
    const std::size_t bad = bomSize + std::max(*utf8Bad, std::get<std::size_t>(gbk));
    const auto [line, column] = lineAndColumn(bytes, bad);
    return SourceReadError::of(std::move(path), message("file_bad_encoding", {std::to_string(line), std::to_string(column)}),
                               line, column);
}

}  // namespace

std::variant<SourceText, SourceReadError> decodeSource(std::string path, std::string_view bytes) {
    auto copy = std::make_shared<const std::string>(bytes);
    std::string_view view = *copy;
    return decodeOwned(std::move(path), view, std::move(copy));
}

Diagnostic diagnosticOf(const SourceReadError& error) {
    Diagnostic d{Severity::Error, DiagnosticKind::Syntax, error.path, error.line, error.column, error.message};
    d.messageId = error.messageId;
    d.messageArguments = error.messageArguments;
    d.unreadable = true;
    return d;
}

std::variant<SourceText, SourceReadError> readSourceFile(const std::string& path) {
#if M350_HAVE_MMAP
    // O_NONBLOCK: opening a FIFO must not wait for a writer; it is refused below anyway.
    const files::FileDescriptor checked(::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK));
    const int fd = checked.get();
    if (fd < 0) return SourceReadError::of(path, message("file_cannot_open", {errnoWords(errno)}));
    struct stat info {};
    if (::fstat(fd, &info) != 0) return SourceReadError::of(path, message("file_cannot_read", {errnoWords(errno)}));
    if (!S_ISREG(info.st_mode)) {
        // /dev/zero or a FIFO never ends: reading one allocated until memory ran out
        return SourceReadError::of(path, message(S_ISDIR(info.st_mode)    ? "file_is_folder"
                                                 : S_ISFIFO(info.st_mode) ? "file_is_fifo"
                                                 : S_ISCHR(info.st_mode) || S_ISBLK(info.st_mode) ? "file_is_device"
                                                                                                    : "file_not_regular"));
    }
    if (static_cast<std::uintmax_t>(info.st_size) > kMostProgramBytes) {
        return SourceReadError::of(path, message("file_too_big_program", {std::to_string(info.st_size / (1024 * 1024)),
                                                                          std::to_string(kMostProgramBytes / (1024 * 1024))}));
    }
    // a small file (a hook, an MDI line, a macro) is read from the descriptor it was checked on:
    // mapping and unmapping it, or opening it again, cost more than the copy, at every MDI line
    constexpr std::uintmax_t kMappedFromBytes = std::uintmax_t{256} << 10;
    if (static_cast<std::uintmax_t>(info.st_size) < kMappedFromBytes) {
        auto bytes = std::make_shared<std::string>();
        char buffer[16384];
        ssize_t n = 0;
        while ((n = ::read(fd, buffer, sizeof buffer)) > 0 || (n < 0 && errno == EINTR)) {
            if (n < 0) {
                continue;
            }
            if (bytes->size() + static_cast<std::size_t>(n) > kMostSourceBytes) {
                return SourceReadError::of(path, message("file_longer_than", {std::to_string(kMostSourceBytes / (1024 * 1024))}));
            }
            bytes->append(buffer, static_cast<std::size_t>(n));
        }
        if (n < 0) return SourceReadError::of(path, message("file_cannot_read", {errnoWords(errno)}));
        std::string_view view = *bytes;
        return decodeOwned(path, view, std::move(bytes));
    }
    if (auto mapped = MappedFile::map(path)) {
        std::string_view bytes = mapped->bytes();
        auto decoded = decodeOwned(path, bytes, mapped, mapped);
        if (mapped->truncated()) {
            return SourceReadError::of(path, message("file_cut_short"));
        }
        return decoded;
    }
#endif
    const std::unique_ptr<std::FILE, FileCloser> file(std::fopen(path.c_str(), "rb"));
    if (!file) return SourceReadError::of(path, message("file_cannot_open", {errnoWords(errno)}));
    auto bytes = std::make_shared<std::string>();
    char buffer[16384];
    std::size_t n = 0;
    while ((n = std::fread(buffer, 1, sizeof buffer, file.get())) > 0) {
        if (bytes->size() + n > kMostSourceBytes) {
            return SourceReadError::of(path, message("file_longer_than", {std::to_string(kMostSourceBytes / (1024 * 1024))}));
        }
        bytes->append(buffer, n);
    }
    if (std::ferror(file.get())) return SourceReadError::of(path, message("file_cannot_read", {errnoWords(errno)}));
    std::string_view view = *bytes;
    return decodeOwned(path, view, std::move(bytes));
}

}  // namespace m350::gcode
