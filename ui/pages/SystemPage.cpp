#include "ui/pages/SystemPage.h"

#include "ui/i18n/Language.h"

#include "core/params/ParameterPages.h"
#include "ui/pages/LevelPrompt.h"
#include "ui/pages/PanelContext.h"
#include "ui/session/UserAccess.h"
#include "ui/widgets/MeasuredLabel.h"
#include "ui/widgets/WrappedLabel.h"

#include <QGridLayout>
#include <QJsonObject>
#include <QLabel>
#include <QVBoxLayout>

#include <filesystem>
#include <variant>

namespace m350::ui {

namespace {

const char* const kFields[] = {"name", "version", "machine", "folder", "params", "programs", "level", "passwords"};

} // namespace

SystemPage::SystemPage(PanelContext& context, QWidget* parent) : Page(context, parent) {
    setObjectName("systemPage");
    auto* column = new QVBoxLayout(this);
    column->setContentsMargins(16, 16, 16, 16);
    auto* grid = new QGridLayout;
    grid->setHorizontalSpacing(16);
    grid->setVerticalSpacing(10);
    int row = 0;
    for (const char* name : kFields) {
        auto* caption = new MeasuredLabel(this);
        caption->setObjectName("infoCaption");
        auto* field = new WrappedLabel(this);
        field->setObjectName(QStringLiteral("system_%1").arg(QLatin1String(name)));
        field->setTextInteractionFlags(Qt::TextSelectableByMouse);
        grid->addWidget(caption, row, 0, Qt::AlignRight | Qt::AlignTop);
        grid->addWidget(field, row, 1);
        captions_.insert(QLatin1String(name), caption);
        fields_.insert(QLatin1String(name), field);
        ++row;
    }
    grid->setColumnStretch(1, 1);
    column->addLayout(grid);
    column->addStretch(1);
    if (const auto* catalogue = std::get_if<params::ParameterCatalogue>(&params::ParameterCatalogue::bundled())) {
        catalogued_ = static_cast<int>(catalogue->all().size());
        const params::ParameterPages pages(*catalogue);
        for (const auto& category : pages.categories()) {
            listed_ += static_cast<int>(category.numbers.size());
        }
    }
    countPrograms();
    retranslate();
}

QString SystemPage::title() const { return tr("System Info", "msg 305"); }

QVector<Page::Softkey> SystemPage::softkeys() const {
    return {{tr("Registration", "msg 536"), false, tr("The simulator needs no licence")},
            {tr("Password Set", "msg 537"), true, {}},
            {tr("System Update", "msg 538"), false, tr("A new version is a new build of M350 Studio")},
            {tr("System Set", "msg 539"), false,
             tr("Date, network and factory reset belong to the controller's system, which is not simulated")},
            {tr("System BackUp", "msg 540"), false, tr("Copy the machine folder to keep the whole machine")},
            {tr("User level"), true, {}}};
}

void SystemPage::softkey(int number) {
    if (number == 2) {
        LevelPrompt::askNewPassword(context());
    } else if (number == 6) {
        LevelPrompt::askLevel(context());
    }
}

// The programs a trainee keeps with the machine: every .nc file in the machine folder and below
// (its macro libraries included), hidden ones left out. std::filesystem, not QDirIterator: its name
// filters compiled a regular expression at every opening of the page.
void SystemPage::countPrograms() {
    namespace fs = std::filesystem;
    programs_ = 0;
    std::error_code error;
    for (fs::recursive_directory_iterator it(context().machineFolder().toStdString(), error), end; !error && it != end;
         it.increment(error)) {
        if (it->path().filename().string().starts_with('.')) { // hidden, as QDir leaves them out
            it.disable_recursion_pending();
            continue;
        }
        const std::string extension = it->path().extension().string();
        std::error_code unreadable; // a dangling link: not a program, the count goes on
        if ((extension == ".nc" || extension == ".NC") && it->is_regular_file(unreadable)) {
            ++programs_;
        }
    }
}

void SystemPage::opened() {
    countPrograms();
    retranslate();
}

void SystemPage::retranslate() {
    captions_["name"]->setText(tr("System Name:", "msg 930"));
    captions_["version"]->setText(tr("Software Ver:", "msg 928"));
    captions_["machine"]->setText(tr("Machine:"));
    captions_["folder"]->setText(tr("Machine folder:"));
    captions_["params"]->setText(tr("Parameters:"));
    captions_["programs"]->setText(tr("Programs:"));
    captions_["level"]->setText(tr("User level:"));
    captions_["passwords"]->setText(tr("Passwords:"));
    fields_["name"]->setText(tr("M350 Studio (a DDCS M350 panel simulator)"));
    fields_["version"]->setText(QStringLiteral(M350_VERSION));
    fields_["folder"]->setText(context().machineFolder());
    fields_["params"]->setText(tr("%1 catalogued, %2 on the Param page").arg(catalogued_).arg(listed_));
    fields_["programs"]->setText(tr("%1 .nc files in the machine folder").arg(programs_));
    if (auto s = context().snapshot()) {
        render(*s);
    }
}

void SystemPage::render(const PanelSnapshot& snapshot) {
    const bool chinese = Language::panelLanguage() == QLatin1String("zh_CN");
    fields_["machine"]->setText(chinese && !snapshot.machineNameZh.isEmpty() ? snapshot.machineNameZh
                                                                             : snapshot.machineName);
    fields_["level"]->setText(UserAccess::levelName(context().session().userLevel()));
    const QString& problem = context().session().passwordsProblem();
    fields_["passwords"]->setText(
        problem.isEmpty()
            ? tr("passwords.toml in order")
            : tr("Locked: passwords.toml cannot be trusted (%1), so only %2 opens and no default password "
                 "comes back. Repair: set new passwords at the highest level, or run "
                 "m350-sim reset-passwords --config FOLDER")
                  .arg(problem, UserAccess::levelName(params::UserLevel::Guest)));
}

QString SystemPage::fieldText(const QString& name) const {
    QLabel* field = fields_.value(name);
    return field ? field->text() : QString();
}

QJsonObject SystemPage::state() const {
    return {{"system_version", fieldText(QStringLiteral("version"))},
            {"system_programs", programs_},
            {"system_level", fieldText(QStringLiteral("level"))},
            {"system_passwords", fieldText(QStringLiteral("passwords"))}};
}

} // namespace m350::ui
