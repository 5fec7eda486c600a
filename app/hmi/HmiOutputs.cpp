#include "app/hmi/HmiOutputs.h"

#include "core/files/OutputFile.h"
#include "core/files/OutputGuard.h"
#include "ui/i18n/Language.h"

#include <QImageWriter>
#include <QStringList>

#include <filesystem>
#include <string_view>
#include <utility>
#include <vector>

namespace m350::hmi {

namespace {

QString imageSuffixes() {
    QStringList suffixes;
    for (const QByteArray& format : QImageWriter::supportedImageFormats()) {
        suffixes << QString::fromLatin1(format);
    }
    return suffixes.join(QStringLiteral(", "));
}

} // namespace

std::optional<QByteArray> screenshotFormat(const std::string& path) {
    std::error_code ec;
    const std::filesystem::path file(path);
    if (!file.has_extension() || (std::filesystem::exists(file, ec) && !std::filesystem::is_regular_file(file, ec))) {
        return QByteArray("png");
    }
    const QByteArray suffix = QByteArray::fromStdString(file.extension().string().substr(1)).toLower();
    if (QImageWriter::supportedImageFormats().contains(suffix)) {
        return suffix;
    }
    return std::nullopt;
}

std::optional<QString> writeOutput(const std::string& path, const QByteArray& bytes) {
    if (auto problem = files::writeOutputFile(path, std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size())))) {
        return QString::fromStdString(problem->in(ui::Language::messageLanguage()));
    }
    return std::nullopt;
}

std::optional<QString> refusedOutput(const HmiOptions& o, const QString& machineFolder) {
    std::vector<files::GuardedPath> guarded{{bilingual("the machine folder", "机床文件夹"), machineFolder.toStdString(), true}};
    if (!o.program.empty()) {
        guarded.push_back({bilingual("the loaded program", "已加载的程序"), o.program, false});
    }
    if (!o.replay.empty()) {
        guarded.push_back({bilingual("the replay being played", "正在回放的录制文件"), o.replay, false});
    }
    if (!o.review.empty()) {
        guarded.push_back({bilingual("the attempt being reviewed", "正在回看的练习记录"), o.review, false});
        guarded.push_back({bilingual("the exercise folder", "练习文件夹"), o.exercise, true});
    }
    std::vector<std::pair<std::string, std::string>> outputs; // option, path
    for (const auto& [option, path] : {std::pair{"--state", &o.state}, {"--screenshot", &o.screenshot}, {"--record", &o.record}}) {
        if (!path->empty()) {
            outputs.emplace_back(option, *path);
        }
    }
    for (std::size_t i = 0; i < outputs.size(); ++i) {
        const auto& [option, path] = outputs[i];
        if (auto refused = files::refusedOutput(option, path, guarded)) {
            return QString::fromStdString(refused->in(ui::Language::messageLanguage()));
        }
        if (auto why = files::unwritableOutput(path)) {
            return QString::fromStdString(files::describeUnwritable(option, path, *why).in(ui::Language::messageLanguage()));
        }
        for (std::size_t j = 0; j < i; ++j) {
            if (files::outputOverGuarded(path, {{"", outputs[j].second, false}}) ||
                std::filesystem::weakly_canonical(std::filesystem::absolute(path)) ==
                    std::filesystem::weakly_canonical(std::filesystem::absolute(outputs[j].second))) {
                return QString::fromStdString(message("hmi_output_twice", {option, path, outputs[j].first})
                                                  .in(ui::Language::messageLanguage()));
            }
        }
    }
    if (!o.screenshot.empty() && !screenshotFormat(o.screenshot)) {
        return QString::fromStdString(message("hmi_not_an_image",
                                              {o.screenshot, std::filesystem::path(o.screenshot).extension().string().substr(1),
                                               imageSuffixes().toStdString()})
                                          .in(ui::Language::messageLanguage()));
    }
    return std::nullopt;
}

} // namespace m350::hmi
