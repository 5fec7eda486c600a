#include "ui/i18n/Language.h"

#include <QApplication>
#include <QFont>
#include <QFontDatabase>
#include <QStringList>

#include <atomic>

namespace m350::ui {

QString findCjkFamily() {
    static const QStringList preferred{"WenQuanYi Micro Hei", "Noto Sans CJK SC", "Noto Sans SC",
                                       "Source Han Sans SC",  "WenQuanYi Zen Hei", "AR PL UMing CN",
                                       "Droid Sans Fallback"};
    const QStringList available = QFontDatabase::families(QFontDatabase::SimplifiedChinese);
    for (const QString& family : preferred) {
        if (available.contains(family)) {
            return family;
        }
    }
    return available.isEmpty() ? QString() : available.front();
}

Language::Language(QApplication& app) : app_(app) {
    cjkFamily_ = findCjkFamily();
    if (!cjkFamily_.isEmpty()) {
        QFont font(cjkFamily_);
        font.setPointSize(10);
        app_.setFont(font);
    }
}

QString Language::fontProblem() const {
    if (!cjkFamily_.isEmpty()) {
        return {};
    }
    return QStringLiteral("m350-hmi: no Chinese (CJK) font found, so Chinese text shows as boxes. Install one, "
                          "e.g. `apt-get install fonts-wqy-microhei` (scripts/deps.sh does), or run with --lang en.");
}

namespace {

QString& chosenLanguage() {
    static QString language = QStringLiteral("zh_CN");
    return language;
}

std::atomic<MessageLanguage>& chosenMessageLanguage() {
    static std::atomic<MessageLanguage> language{MessageLanguage::Chinese};
    return language;
}

} // namespace

namespace {

MessageLanguage messageLanguageOf(const QString& language) {
    return language == QLatin1String("en") ? MessageLanguage::English : MessageLanguage::Chinese;
}

} // namespace

MessageLanguage Language::spoken() const { return messageLanguageOf(current_); }

QString Language::say(const Message& words) const { return QString::fromStdString(words.in(spoken())); }

MessageLanguage spokenBy(const Language* language) { return language ? language->spoken() : MessageLanguage::Chinese; }

QString Language::panelLanguage() {
    return chosenLanguage();
}

MessageLanguage Language::messageLanguage() {
    return chosenMessageLanguage().load();
}

bool Language::set(const QString& language, QString* error) {
    if (language != QLatin1String("zh_CN") && language != QLatin1String("en")) {
        if (error) {
            *error = QStringLiteral("unknown language '%1' (zh_CN or en)").arg(language);
        }
        return false;
    }
    auto translator = std::make_unique<QTranslator>();
    if (!translator->load(QStringLiteral(":/i18n/m350_%1.qm").arg(language))) {
        if (error) {
            *error = QStringLiteral("the %1 translation is missing from this build").arg(language);
        }
        return false;
    }
    if (translator_) {
        QApplication::removeTranslator(translator_.get());
    }
    translator_ = std::move(translator);
    QApplication::installTranslator(translator_.get()); // sends LanguageChange to every widget
    current_ = language;
    chosenLanguage() = language;
    chosenMessageLanguage() = messageLanguageOf(language);
    return true;
}

} // namespace m350::ui
