#pragma once

#include "core/common/Message.h"

#include <QString>
#include <QTranslator>

#include <memory>

class QApplication;

namespace m350::ui {

// The panel's language (zh_CN by default, en) and its font. Chinese needs a CJK font, which a
// stock Debian machine lacks: the panel picks one explicitly and says so when there is none.
class Language {
public:
    explicit Language(QApplication& app);
    // Installs the translation; false (and a message) for an unknown language.
    bool set(const QString& language, QString* error = nullptr);
    const QString& current() const { return current_; }
    // The message table's language that this one is (en: English, zh_CN: Chinese).
    MessageLanguage spoken() const;
    // A message of the table in this language.
    QString say(const Message& words) const;
    // The language the panel says the core's messages in (AlarmText): the last one set, zh_CN
    // before any.
    static QString panelLanguage();
    // The same for the message table; safe to read from the session's worker thread (its load
    // errors, DiagnosticText).
    static MessageLanguage messageLanguage();
    // The CJK font family in use, or empty when the machine has none (see fontProblem()).
    const QString& cjkFamily() const { return cjkFamily_; }
    QString fontProblem() const;

private:
    QApplication& app_;
    std::unique_ptr<QTranslator> translator_;
    QString current_;
    QString cjkFamily_;
};

// The message table's language of `language`; Chinese, the panel's default, when there is none.
MessageLanguage spokenBy(const Language* language);

// The CJK families the panel prefers, best first (fonts-wqy-microhei is what scripts/deps.sh installs).
QString findCjkFamily();

} // namespace m350::ui
